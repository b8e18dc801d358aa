#!/usr/bin/env python3
"""Top view of the planner example's scene from its CSV files (written by `planner`).

Usage: python3 plot_planner.py [DIR]   (reads DIR/planner_segments.csv and
DIR/planner_obstacles.csv, writes DIR/planner.png; DIR defaults to the current directory)

Obstacles are drawn as the convex hulls of their vertices projected on the floor; segments
are coloured by mink's mdd() verdict (free, blocked), with the blocked segments that FCL's
1 % sampling calls free, and those FCL's conservative advancement calls free, on top.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Polygon  # noqa: E402


def hull2d(points):
    """Convex hull (Andrew's monotone chain), counter-clockwise, of 2-D points."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "."
    obstacles = {}
    with open(os.path.join(folder, "planner_obstacles.csv")) as f:
        for row in csv.DictReader(f):
            obstacles.setdefault(int(row["obstacle"]), []).append((float(row["x"]), float(row["y"])))
    with open(os.path.join(folder, "planner_segments.csv")) as f:
        segments = list(csv.DictReader(f))

    fig, ax = plt.subplots(figsize=(9, 9))
    for pts in obstacles.values():
        ax.add_patch(Polygon(hull2d(pts), closed=True, facecolor="0.55", edgecolor="0.25", linewidth=0.6))

    styles = [  # drawn in this order, later on top
        ("free (mink mdd)", lambda r: r["truth_mink_mdd"] == "free", dict(color="tab:green", lw=0.5, alpha=0.5)),
        ("blocked (mink mdd)", lambda r: r["truth_mink_mdd"] == "blocked", dict(color="tab:red", lw=0.5, alpha=0.5)),
        ("blocked, FCL conservative advancement (libccd) says free",
         lambda r: r["truth_mink_mdd"] == "blocked" and r["fcl_ca_libccd"] == "free", dict(color="tab:purple", lw=1.6)),
        ("blocked, FCL 1 % sampling says free",
         lambda r: r["truth_mink_mdd"] == "blocked" and r["fcl_101"] == "free", dict(color="tab:orange", lw=2.4)),
    ]
    for label, pick, style in styles:
        chosen = [r for r in segments if pick(r)]
        for i, r in enumerate(chosen):
            ax.plot([float(r["x0"]), float(r["x1"])], [float(r["y0"]), float(r["y1"])],
                    label=f"{label} ({len(chosen)})" if i == 0 else None, **style)
        if not chosen:
            ax.plot([], [], label=f"{label} (0)", **style)

    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"planner: {len(segments)} straight-line segments, {len(obstacles)} obstacles (top view)")
    ax.legend(loc="upper right", fontsize=8, framealpha=0.9)
    out = os.path.join(folder, "planner.png")
    fig.savefig(out, dpi=130, bbox_inches="tight")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
