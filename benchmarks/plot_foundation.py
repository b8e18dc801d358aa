#!/usr/bin/env python3
"""Plots the CSV written by mink_foundation_bench.

usage: plot_foundation.py [foundation.csv] [foundation.png]
defaults: benchmarks/results/foundation.csv -> benchmarks/results/foundation.png

Panels: (a) support-query time per method against n, median with min..max bars;
(b) hull and hierarchy build time against n with the fitted a * n log2 n, beside
CGAL's convex_hull_3 and FCL's Convex on the same points when the bench has them;
(c) the crossover of the hierarchy against a cold hill-climb on small shapes, with the
chosen defaults::kHierarchyMinVertices read from the CSV comment line;
(d) the parameter sweep (query time for each removed-degree bound and top size).
All times are thread CPU time (see foundation_bench.cpp).
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    rows, comments = [], []
    with open(path, newline="") as f:
        lines = []
        for line in f:
            if line.startswith("#"):
                comments.append(line[1:].strip())
            else:
                lines.append(line)
    for r in csv.DictReader(lines):
        for k in ("n", "vertices", "reps"):
            r[k] = int(r[k])
        for k in ("median_us", "min_us", "max_us", "q1_us", "q3_us", "wall_median_us"):
            r[k] = float(r[k])
        rows.append(r)
    return rows, comments


def select(rows, section, method=None, param=None):
    out = [r for r in rows if r["section"] == section
           and (method is None or r["method"] == method)
           and (param is None or r["param"] == param)]
    return sorted(out, key=lambda r: r["n"])


def errorbars(ax, rs, label, scale=1.0, **kw):
    if not rs:
        return
    x = [r["n"] for r in rs]
    y = [r["median_us"] * scale for r in rs]
    lo = [(r["median_us"] - r["min_us"]) * scale for r in rs]
    hi = [(r["max_us"] - r["median_us"]) * scale for r in rs]
    ax.errorbar(x, y, yerr=[lo, hi], marker="o", capsize=3, label=label, **kw)


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "benchmarks/results/foundation.csv"
    dst = sys.argv[2] if len(sys.argv) > 2 else "benchmarks/results/foundation.png"
    rows, comments = read(src)
    machine = next((c for c in comments if c.startswith("machine:")), "")

    fig, axes = plt.subplots(2, 2, figsize=(13, 10))
    (a, b), (c, d) = axes

    errorbars(a, select(rows, "query", "dk", "random"), "DK hierarchy")
    errorbars(a, select(rows, "query", "cold", "random"), "hill-climb, cold (vertex 0)")
    errorbars(a, select(rows, "query", "warm", "slow"), "hill-climb, warm (slow directions)")
    errorbars(a, select(rows, "query", "dk", "slow"), "DK hierarchy (slow directions)", linestyle="--")
    errorbars(a, select(rows, "query", "brute", "random"), "brute-force scan")
    a.set_xscale("log")
    a.set_yscale("log")
    a.set_xlabel("vertices n (ellipsoid 2:2:5)")
    a.set_ylabel("time per support query [us]")
    a.set_title("(a) support queries, double (median, min..max)")
    a.grid(True, which="both", alpha=0.3)
    a.legend(fontsize=8)

    errorbars(b, select(rows, "build", "hull"), "hull (fromPoints)", scale=1e-3)
    hier = select(rows, "build", "hierarchy")
    errorbars(b, hier, "DK hierarchy", scale=1e-3)
    # The anchors, when the bench was built with CGAL (and FCL): same points, same run.
    errorbars(b, select(rows, "build", "cgal_hull"), "CGAL convex_hull_3 (Epick, Surface_mesh)",
              scale=1e-3, linestyle="--")
    errorbars(b, select(rows, "build", "fcl_convex"), "FCL Convex (CGAL hull + fcl::Convexd)",
              scale=1e-3, linestyle="--")
    fit = [r for r in rows if r["section"] == "fit"]
    if fit and hier:
        coef = fit[0]["median_us"]
        xs = [hier[0]["n"] * (hier[-1]["n"] / hier[0]["n"]) ** (i / 40) for i in range(41)]
        b.plot(xs, [coef * x * math.log2(x) * 1e-3 for x in xs], "k:",
               label="fit %.3g us * n log2 n" % coef)
    b.set_xscale("log")
    b.set_yscale("log")
    b.set_xlabel("vertices n")
    b.set_ylabel("build time [ms]")
    b.set_title("(b) builds (median, min..max)")
    b.grid(True, which="both", alpha=0.3)
    b.legend(fontsize=8)

    errorbars(c, select(rows, "crossover", "dk"), "DK hierarchy")
    errorbars(c, select(rows, "crossover", "cold"), "hill-climb, cold (vertex 0)")
    cross = [r for r in rows if r["section"] == "crossover_n"]
    if cross and cross[0]["n"] > 0:
        c.axvline(cross[0]["n"], color="gray", linestyle="--",
                  label="DK faster from n = %d on" % cross[0]["n"])
    defaults = next((x for x in comments if x.startswith("defaults:")), "")
    if "kHierarchyMinVertices=" in defaults:
        nmin = int(defaults.split("kHierarchyMinVertices=")[1].split()[0])
        c.axvline(nmin, color="red", linestyle=":", label="kHierarchyMinVertices = %d" % nmin)
    c.set_xscale("log")
    c.set_xlabel("vertices n")
    c.set_ylabel("time per support query [us]")
    c.set_title("(c) crossover on small shapes (median, min..max over shapes x batches)")
    c.grid(True, which="both", alpha=0.3)
    c.legend(fontsize=8)

    sweep = [r for r in rows if r["section"] == "sweep_query"]
    if sweep:
        labels = [r["param"] for r in sweep]
        y = [r["median_us"] for r in sweep]
        err = [[r["median_us"] - r["q1_us"] for r in sweep], [r["q3_us"] - r["median_us"] for r in sweep]]
        d.bar(range(len(sweep)), y, yerr=err, capsize=2, color="tab:blue")
        d.set_xticks(range(len(sweep)))
        d.set_xticklabels(labels, rotation=60, ha="right", fontsize=7)
        d.set_ylabel("time per DK query [us] (median, IQR)")
        d.set_title("(d) parameter sweep at n = %d" % sweep[0]["n"])
        d.grid(True, axis="y", alpha=0.3)

    fig.suptitle("mink foundation benchmark — " + machine, fontsize=10)
    fig.tight_layout()
    fig.savefig(dst, dpi=110)
    print("wrote", dst)


if __name__ == "__main__":
    main()
