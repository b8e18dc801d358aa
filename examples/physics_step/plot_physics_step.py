#!/usr/bin/env python3
"""Plots the CSV written by mink_physics_step (one row per pair query).

Left: |TOI error| against the exact reference (fraction of the step), per method, over the
queries where both the method and the reference report an impact (cumulative share).
Right: time per pair query, per method (cumulative share).
Also prints mink's queries by MddResult::path (Cache, Certificate, Search, None = NoContact...).

Usage: python3 plot_physics_step.py physics_step.csv [out.png]   (default: beside the CSV)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHODS = [
    ("mink", "mink mdd"),
    ("mink_cold", "mink mdd, no cache"),
    ("fcl_ca_libccd", "FCL CA (libccd)"),
    ("fcl_ca_indep", "FCL CA (indep)"),
    ("fcl_discrete", "FCL discrete"),
    ("exact", "exact (CGAL)"),
]
FLOOR = 1e-17  # errors of exactly 0 are drawn here (log axis)


def main():
    path = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.splitext(path)[0] + ".png"
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))

    fig, (ax_err, ax_us) = plt.subplots(1, 2, figsize=(11, 4.2))
    for key, label in METHODS:
        us = sorted(float(r[key + "_us"]) for r in rows)
        share = [(i + 1) / len(us) for i in range(len(us))]
        ax_us.plot(us, share, label=label)
        if key in ("fcl_discrete", "exact"):
            continue  # discrete has no time of impact; the reference is the zero
        errs = sorted(
            max(abs(float(r[key + "_toi"]) - float(r["exact_toi"])), FLOOR)
            for r in rows
            if r[key + "_hit"] == "1" and r["exact_hit"] == "1"
        )
        missed = sum(1 for r in rows if r[key + "_hit"] == "0" and r["exact_hit"] == "1")
        if errs:
            share = [(i + 1) / len(errs) for i in range(len(errs))]
            style = "--" if key == "mink_cold" else "-"  # on top of "mink" when they agree
            ax_err.plot(errs, share, style, label=f"{label} ({missed} missed)")
    ax_err.set_xscale("log")
    ax_err.set_xlabel("|TOI error| (fraction of the step), vs exact")
    ax_err.set_ylabel("share of impacts found")
    ax_err.set_title(f"time of impact, {sum(r['exact_hit'] == '1' for r in rows)} exact impacts")
    ax_err.legend(fontsize=8)
    ax_err.grid(True, which="both", alpha=0.3)
    ax_us.set_xscale("log")
    ax_us.set_xlabel("time per pair query (µs)")
    ax_us.set_ylabel("share of queries")
    ax_us.set_title(f"{len(rows)} pair queries")
    ax_us.legend(fontsize=8)
    ax_us.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)

    # Which step of mdd() answered (MddResult::path): how much the per-pair MddCache serves.
    print("mink mdd by path: path, queries, median us")
    for path_name in sorted({r["mink_path"] for r in rows}):
        us = sorted(float(r["mink_us"]) for r in rows if r["mink_path"] == path_name)
        print(f"  {path_name:12s} {len(us):7d} {us[len(us) // 2]:9.2f}")


if __name__ == "__main__":
    main()
