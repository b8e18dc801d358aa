#!/usr/bin/env python3
"""Gathers run_cpd_trade.sh's runs of mink_cpd_query_bench (one CSV per alpha, beta) into
one table of the coherent CPD query per (alpha, beta): the median time per query on each
of the paper's scenes and over the small motions, Approximate frames, the worst CPD / PD
depth ratio and the worst turn of the direction per frame.

usage: cpd_trade_table.py RUNS_DIR OUT.csv   (prints the Markdown table)
"""
import csv
import glob
import os
import re
import statistics
import sys


def rows(path):
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    return list(csv.DictReader(lines))


def main():
    runs, out = sys.argv[1], sys.argv[2]
    table = []
    for path in sorted(glob.glob(os.path.join(runs, "alpha*_beta*.csv"))):
        if path.endswith("_frames.csv"):
            continue
        m = re.search(r"alpha([0-9.]+)_beta([0-9.]+)\.csv$", path)
        alpha, beta = float(m.group(1)), float(m.group(2))
        cpd = [r for r in rows(path) if r["method"] == "cpd"]
        paper = {r["scene"]: r for r in cpd if r["paper_ms"] != "nan"}
        small = [r for r in cpd if r["paper_ms"] == "nan"]
        frames = sum(int(r["frames_done"]) for r in cpd)
        planned = sum(int(r["frames"]) for r in cpd)
        table.append({
            "alpha": alpha,
            "beta": beta,
            **{s: float(r["median_ms"]) for s, r in paper.items()},
            "small_ms": statistics.median(float(r["median_ms"]) for r in small) if small else float("nan"),
            "approximate": sum(int(r["approximate"]) for r in cpd),
            "frames": frames,
            "planned": planned,
            "ratio_max": max(float(r["depth_ratio_max"]) for r in cpd),
            "turn_max_small": max(float(r["turn_max_deg"]) for r in small) if small else float("nan"),
            "turn_max_paper": max(float(r["turn_max_deg"]) for r in paper.values()) if paper else float("nan"),
        })
    if not table:
        sys.exit("no runs in " + runs)
    scenes = [k for k in table[0] if "/" in k]
    cols = ["alpha", "beta"] + scenes + ["small_ms", "approximate", "frames", "planned", "ratio_max",
                                         "turn_max_small", "turn_max_paper"]
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols)
        w.writeheader()
        for t in table:
            w.writerow({c: t.get(c, "") for c in cols})
    head = ["alpha", "beta"] + [s + " ms" for s in scenes] + [
        "small motions ms (median of medians)", "Approximate frames", "CPD / PD depth max",
        "turn max, small motions (°)", "turn max, paper scenes (°)"]
    print("| " + " | ".join(head) + " |")
    print("| " + " | ".join(["---:"] * len(head)) + " |")
    for t in table:
        cells = [f"{t['alpha']:g}", f"{t['beta']:g}"] + [f"{t.get(s, float('nan')):.3f}" for s in scenes] + [
            f"{t['small_ms']:.3f}", f"{t['approximate']} of {t['frames']}" +
            ("" if t["frames"] == t["planned"] else f" (of {t['planned']} planned: a scene hit its time limit)"),
            f"{t['ratio_max']:.3f}", f"{t['turn_max_small']:.2f}", f"{t['turn_max_paper']:.2f}"]
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
