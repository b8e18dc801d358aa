#!/usr/bin/env python3
"""Plots the CSVs written by mink_mdd_bench (benchmarks/mdd_bench.cpp).

usage: plot_mdd.py [results_dir]      (default benchmarks/results)

Reads mdd_paper.csv, mdd_scaling.csv, mdd_coherence.csv, mdd_precision.csv and writes
  mdd_paper.png      per pair: median time per query of mink and its peers (log scale),
                     and cold against warm-cache queries on the coherence paths;
  mdd_scaling.png    log-log: time per query against vertices per shape (ellipsoid pairs),
                     and the build times;
  mdd_precision.png  log-log Pareto plot: time per query against max (filled) and median
                     (hollow) error against the exact reference, per scalar type; an error
                     of exactly 0 (the rational type) is drawn at the bottom of the axis.
All times are medians of per-query steady_clock times (see mdd_bench.cpp).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    rows, comments = [], []
    if not os.path.exists(path):
        return rows, comments
    with open(path, newline="") as f:
        lines = []
        for line in f:
            if line.startswith("#"):
                comments.append(line[1:].strip())
            else:
                lines.append(line)
    for r in csv.DictReader(lines):
        for k in ("count",):
            r[k] = int(r[k])
        for k in ("median_us", "mean_us", "q1_us", "q3_us", "max_err", "median_err", "value"):
            try:
                r[k] = float(r[k])
            except ValueError:
                r[k] = float("nan")
        rows.append(r)
    return rows, comments


def pick(rows, section=None, case=None, method=None, subset=None):
    return [r for r in rows
            if (section is None or r["section"] == section)
            and (case is None or r["case"] == case)
            and (method is None or r["method"] == method)
            and (subset is None or r["subset"] == subset)]


def one(rows, **kw):
    found = pick(rows, **kw)
    return found[0] if found else None


def machine(comments):
    return next((c for c in comments if c.startswith("machine:")), "")


def plot_paper(d):
    rows, comments = read(os.path.join(d, "mdd_paper.csv"))
    coh, _ = read(os.path.join(d, "mdd_coherence.csv"))
    if not rows:
        return
    pairs = []
    for r in rows:
        if r["section"] == "paper" and r["case"] != "all" and r["case"] not in pairs:
            pairs.append(r["case"])
    series = [
        ("mink_cold", "all", "mink (cold)"),
        ("mink_intersects", "all", "mink intersects (yes/no)"),
        ("ccd_gjk", "all", "libccd GJK (yes/no)"),
        ("ccd_mpr", "two_calls", "libccd MPR directional (2 calls, penetrating)"),
        ("fcl_signed", "all", "FCL signed distance"),
        ("bullet_subsimplex_cast", "all", "Bullet subsimplex casts"),
        ("bullet_gjk_cast", "all", "Bullet GJK casts"),
    ]
    fig, (a, b) = plt.subplots(1, 2, figsize=(16, 6), gridspec_kw={"width_ratios": [3, 1]})
    width = 0.8 / len(series)
    for k, (method, subset, label) in enumerate(series):
        ys, lo, hi = [], [], []
        for p in pairs:
            r = one(rows, section="paper", case=p, method=method, subset=subset)
            y = r["median_us"] if r else float("nan")
            ys.append(y)
            lo.append(y - r["q1_us"] if r else 0)
            hi.append(r["q3_us"] - y if r else 0)
        xs = [i + (k - len(series) / 2 + 0.5) * width for i in range(len(pairs))]
        a.bar(xs, ys, width, yerr=[lo, hi], capsize=1.5, label=label)
    a.set_xticks(range(len(pairs)))
    a.set_xticklabels(pairs)
    a.set_yscale("log")
    a.set_ylabel("time per query [us] (median, IQR)")
    a.set_title("(a) the paper's ten pairs: mink and its peers on the same queries")
    a.grid(True, axis="y", which="both", alpha=0.3)
    a.legend(fontsize=7, ncol=2)
    if coh:
        names = []
        for r in coh:
            if r["section"] == "coherence" and r["case"] not in names:
                names.append(r["case"])
        for k, (method, label) in enumerate([("mink_warm", "warm (cache)"), ("mink_cold", "cold (no hints)"),
                                             ("mink_nocache", "no cache")]):
            ys = []
            for n in names:
                r = one(coh, section="coherence", case=n, method=method, subset="path")
                ys.append(r["median_us"] if r else float("nan"))
            b.bar([i + (k - 1) * 0.27 for i in range(len(names))], ys, 0.27, label=label)
        b.set_xticks(range(len(names)))
        b.set_xticklabels(names)
        b.set_ylabel("time per query [us] (median)")
        b.set_title("(b) coherent path: warm vs cold")
        b.grid(True, axis="y", alpha=0.3)
        b.legend(fontsize=8)
    fig.suptitle("mink MDD vs peers — " + machine(comments), fontsize=10)
    fig.tight_layout()
    out = os.path.join(d, "mdd_paper.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


def plot_scaling(d):
    rows, comments = read(os.path.join(d, "mdd_scaling.csv"))
    if not rows:
        return
    sizes = sorted({int(r["case"]) for r in rows if r["section"] == "scaling" and r["case"].isdigit()})
    fig, (a, b) = plt.subplots(1, 2, figsize=(14, 6))
    series = [
        ("mink_cold", "all", "mink cold", "o-"),
        ("mink_nocache", "all", "mink, no cache", "o--"),
        ("mink_warm", "path", "mink warm (coherent path)", "s-"),
        ("ccd_gjk", "all", "libccd GJK (yes/no)", "^-"),
        ("ccd_mpr", "two_calls", "libccd MPR directional (penetrating)", "v-"),
        ("fcl_signed", "all", "FCL signed distance", "D-"),
        ("bullet_subsimplex_cast", "all", "Bullet subsimplex casts", "x-"),
    ]
    for method, subset, label, style in series:
        xs, ys = [], []
        for n in sizes:
            r = one(rows, section="scaling", case=str(n), method=method, subset=subset)
            if r and not math.isnan(r["median_us"]):
                xs.append(n)
                ys.append(r["median_us"])
        if xs:
            a.plot(xs, ys, style, label=label)
    a.set_xscale("log")
    a.set_yscale("log")
    a.set_xlabel("vertices per shape (ellipsoid 2:2:5)")
    a.set_ylabel("time per query [us] (median)")
    a.set_title("(a) queries")
    a.grid(True, which="both", alpha=0.3)
    a.legend(fontsize=8)
    for method, label in [("hull_ms", "hull + adjacency (fromPoints)"), ("dk_ms", "DK hierarchy"),
                          ("fcl_convex_ms", "FCL Convex (CGAL hull + fcl::Convexd)")]:
        xs, ys = [], []
        for n in sizes:
            r = one(rows, section="scaling_build", case=str(n), method=method)
            if r and r["value"] > 0:
                xs.append(n)
                ys.append(r["value"])
        if xs:
            b.plot(xs, ys, "o-", label=label)
    b.set_xscale("log")
    b.set_yscale("log")
    b.set_xlabel("vertices per shape")
    b.set_ylabel("build time per shape [ms]")
    b.set_title("(b) builds (one run each)")
    b.grid(True, which="both", alpha=0.3)
    b.legend(fontsize=8)
    fig.suptitle("mink MDD scaling — " + machine(comments), fontsize=10)
    fig.tight_layout()
    out = os.path.join(d, "mdd_scaling.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


def plot_precision(d):
    rows, comments = read(os.path.join(d, "mdd_precision.csv"))
    if not rows:
        return
    # certified: mddExact<Gmpq> on the double shapes and poses, exact for those numbers;
    # its error against the reference (exact rotation) is the rotation's rounding to double.
    types = [("float", "tab:red"), ("double", "tab:blue"), ("long_double", "tab:green"), ("certified", "tab:orange"),
             ("exact_gmpq", "tab:purple")]
    errs = [r["max_err"] for r in rows if r["section"] == "precision" and r["max_err"] > 0]
    floor = min(errs) / 100 if errs else 1e-18
    fig, ax = plt.subplots(figsize=(9, 6.5))
    for t, color in types:
        per = pick(rows, section="precision", method=t, subset="all")
        pairs = [r for r in per if r["case"] != "all"]
        agg = [r for r in per if r["case"] == "all"]
        ax.scatter([r["median_us"] for r in pairs], [max(r["max_err"], floor) for r in pairs], color=color,
                   s=14, alpha=0.45)
        for r in agg:
            ax.scatter([r["median_us"]], [max(r["max_err"], floor)], color=color, s=110, marker="o",
                       edgecolors="k", label="%s: max error %s" % (t, "0 (exact)" if r["max_err"] == 0 else
                                                                    "%.2g" % r["max_err"]))
            ax.scatter([r["median_us"]], [max(r["median_err"], floor)], facecolors="none", edgecolors=color, s=110,
                       marker="o")
    ax.axhline(floor, color="gray", linestyle=":", linewidth=0.8)
    ax.annotate("error exactly 0 (drawn here)", (0.01, floor), xycoords=("axes fraction", "data"), fontsize=7,
                color="gray", va="bottom")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per query [us] (median)")
    ax.set_ylabel("error against the exact reference [length units] (shapes of radius 5)")
    ax.set_title("speed-accuracy: mink per scalar type (big: all pairs; small: per pair; hollow: median error)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.suptitle("mink MDD precision — " + machine(comments), fontsize=10)
    fig.tight_layout()
    out = os.path.join(d, "mdd_precision.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "benchmarks/results"
    plot_paper(d)
    plot_scaling(d)
    plot_precision(d)


if __name__ == "__main__":
    main()
