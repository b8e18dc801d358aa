#!/usr/bin/env python3
"""Plots benchmarks/results/cpd_table2.csv (mink_cpd_bench): ms per update of each method
on each scene, log scale, beside the CPD paper's Table 2 (hollow bars).

usage: plot_cpd.py [cpd_table2.csv] [cpd_table2.png]
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "results", "cpd_table2.csv")
dst = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "results", "cpd_table2.png")

rows = []
with open(src) as f:
    lines = [line for line in f if not line.startswith("#")]
for r in csv.DictReader(lines):
    rows.append(r)


def num(x):
    try:
        v = float(x)
    except ValueError:
        return math.nan
    return v


scenes = []
for r in rows:
    if r["scene"] not in scenes:
        scenes.append(r["scene"])
methods = [("full", "full (mink)"), ("cgal", "CGAL minkowski_sum_3"), ("brute", "brute force"),
           ("sphere_tree", "sphere tree (BSH)"), ("convex_maps", "convex maps (coherent)"),
           ("box_trees", "box trees (default)")]
colours = ["#444444", "#999999", "#d62728", "#1f77b4", "#2ca02c", "#9467bd"]
by = {(r["scene"], r["method"]): r for r in rows}

fig, ax = plt.subplots(figsize=(max(8, 1.6 * len(scenes)), 5))
width = 0.8 / len(methods)
handles = []
top = 1.0
for m, (key, label) in enumerate(methods):
    xs, ys, lower, paper_x, paper_y = [], [], [], [], []
    for s, scene in enumerate(scenes):
        r = by.get((scene, key))
        if r is None:
            continue
        x = s - 0.4 + width * (m + 0.5)
        v = num(r["median_ms"])
        if not math.isnan(v):
            xs.append(x)
            ys.append(v)
        elif r["note"].startswith("stopped after"):
            # A lower bound: the child process was stopped ("... > N ms CPU" when known).
            note = r["note"]
            if "ms CPU" in note:
                lower.append((x, float(note.split(">")[1].split()[0])))
            else:
                lower.append((x, 1e3 * float(note.split()[2])))
        p = num(r["paper_ms"])
        if not math.isnan(p):
            paper_x.append(x)
            paper_y.append(p)
            top = max(top, p)
    handles.append(Patch(facecolor=colours[m], label=label))
    if xs:
        ax.bar(xs, ys, width, color=colours[m])
        top = max(top, max(ys))
    for x, v in lower:
        ax.bar([x], [v], width, color="none", edgecolor=colours[m], hatch="//")
        ax.annotate("> %.0f s" % (v / 1e3), (x, v), ha="center", va="bottom", fontsize=7, rotation=90)
        top = max(top, v)
    if paper_x:
        ax.scatter(paper_x, paper_y, marker="_", s=120, color="black", zorder=3)
handles.append(Line2D([], [], marker="_", markersize=12, linestyle="none", color="black",
                      label="paper, Table 2 (i7 3.6 GHz)"))
handles.append(Patch(facecolor="none", edgecolor="black", hatch="//", label="stopped: lower bound (CPU)"))
ax.set_yscale("log")
ax.set_ylim(top=top * 30)
ax.set_xticks(range(len(scenes)))
ax.set_xticklabels(scenes, rotation=20, ha="right")
ax.set_ylabel("ms per update (median, thread CPU time)")
ax.set_title("Boundary of M = A ⊕ −B: whole, and local in a ball of radius 50 (M radius 250)")
ax.legend(handles=handles, fontsize=8, loc="upper left", ncol=3)
ax.grid(axis="y", which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(dst, dpi=120)
print("wrote", dst)
