#!/usr/bin/env python3
"""Plots benchmarks/results/cpd_query_frames.csv (mink_cpd_query_bench): per scene, along
the motion, the turn of the direction since the previous frame (degrees, symmetric-log
scale) of the coherent CPD query, of CPD reset before each query, of the Euclidean PD and
of FCL's deepest contact normal (when the benchmark was built with FCL); and beside it the
depth of each (FCL's: the largest contact penetration_depth of a triangle pair).

usage: plot_cpd_query.py [cpd_query_frames.csv] [cpd_query.png]
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "results", "cpd_query_frames.csv")
dst = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "results", "cpd_query.png")

with open(src) as f:
    lines = [line for line in f if not line.startswith("#")]
rows = list(csv.DictReader(lines))


def num(x):
    try:
        return float(x)
    except ValueError:
        return math.nan


scenes = []
for r in rows:
    if r["scene"] not in scenes:
        scenes.append(r["scene"])
styles = {
    "cpd": dict(color="#2ca02c", lw=1.8, label="CPD (coherent)"),
    "fresh": dict(color="#1f77b4", lw=0.9, ls=":", label="CPD, reset each frame"),
    "pd": dict(color="#d62728", lw=1.2, ls="--", label="Euclidean PD"),
    "fcl": dict(color="#7f7f7f", lw=0.9, ls="-.", label="FCL contact (deepest)"),
}

fig, axes = plt.subplots(len(scenes), 2, figsize=(11, 2.1 * len(scenes) + 0.8), squeeze=False)
for i, scene in enumerate(scenes):
    turn_ax, depth_ax = axes[i]
    for method, style in styles.items():
        sel = [r for r in rows if r["scene"] == scene and r["method"] == method]
        frames = [int(r["frame"]) for r in sel]
        turns = [num(r["turn_deg"]) for r in sel]
        depths = [num(r["depth"]) if r["status"] != "Separated" else math.nan for r in sel]
        turn_ax.plot(frames, turns, **style)
        depth_ax.plot(frames, depths, **style)
        approx = [(f, d) for f, d, r in zip(frames, depths, sel) if r["status"] == "Approximate"]
        if approx:
            depth_ax.scatter(*zip(*approx), marker="x", color=style["color"], s=16, zorder=3)
    turn_ax.set_yscale("symlog", linthresh=0.1)
    turn_ax.set_ylim(0, 300)
    turn_ax.set_yticks([0, 0.1, 1, 10, 90, 180])
    turn_ax.set_yticklabels(["0", "0.1", "1", "10", "90", "180"])
    turn_ax.set_ylabel(scene, fontsize=9)
    turn_ax.grid(alpha=0.3)
    depth_ax.grid(alpha=0.3)
    if i == 0:
        turn_ax.set_title("turn of the direction since the last frame (°)", fontsize=10)
        depth_ax.set_title("depth (length unit of the meshes; x: Approximate)", fontsize=10)
        depth_ax.legend(fontsize=8, loc="best")
    if i == len(scenes) - 1:
        turn_ax.set_xlabel("frame")
        depth_ax.set_xlabel("frame")
fig.suptitle("CPD query along motions beside the Euclidean penetration depth (mink_cpd_query_bench)", fontsize=11)
fig.tight_layout()
fig.savefig(dst, dpi=110)
print("wrote", dst)
