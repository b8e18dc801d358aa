#!/usr/bin/env python3
"""Plots the CSV written by mink_mdd_degenerate_bench (benchmarks/mdd_degenerate_bench.cpp).

usage: plot_mdd_degenerate.py [results_dir]      (default benchmarks/results)

Reads mdd_degenerate.csv and writes mdd_degenerate.png: per family, log-log, the median
time per mdd() query against n (polygon size), degenerate contact (filled) beside its
generic twin (the same shapes, Q turned by 0.01 rad; hollow), with the worst degenerate
query of each size as a thin line, the 1 ms target as a dashed line. Axis-aligned boxes
have no n (n = 4 in the CSV) and are drawn as a single pair of points.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    comments, lines = [], []
    with open(path, newline="") as f:
        for line in f:
            if line.startswith("#"):
                comments.append(line[1:].strip())
            else:
                lines.append(line)
    rows = list(csv.DictReader(lines))
    for r in rows:
        r["n"] = int(r["n"])
        for k in ("degenerate_us", "generic_us", "degenerate_max_us"):
            r[k] = float(r[k])
    return rows, comments


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "benchmarks/results"
    rows, comments = read(os.path.join(outdir, "mdd_degenerate.csv"))
    families = []
    for r in rows:
        if r["family"] not in families:
            families.append(r["family"])
    fig, ax = plt.subplots(figsize=(10.5, 5.5))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, fam in enumerate(families):
        rs = sorted((r for r in rows if r["family"] == fam), key=lambda r: r["n"])
        n = [r["n"] for r in rs]
        c = colors[i % len(colors)]
        ax.plot(n, [r["degenerate_us"] for r in rs], "o-", color=c, label=fam + " (degenerate)")
        ax.plot(n, [r["generic_us"] for r in rs], "o--", color=c, mfc="none", label=fam + " (generic twin)")
        ax.plot(n, [r["degenerate_max_us"] for r in rs], "-", color=c, lw=0.6, alpha=0.6)
    ax.axhline(1000.0, color="k", ls=":", lw=1)
    ax.text(17, 1100, "1 ms target (n = 1024); thin lines: slowest degenerate query", fontsize=8)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_ylim(top=3000)
    ax.set_xlabel("n (polygon size of the prisms, cylinders and cones)")
    ax.set_ylabel("median time per mdd() query, no cache [us]")
    title = "MDD worst cases: degenerate contacts beside generic twins"
    if comments:
        title += "\n" + comments[0]
    ax.set_title(title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    out = os.path.join(outdir, "mdd_degenerate.png")
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
