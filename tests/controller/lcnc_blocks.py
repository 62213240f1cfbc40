#!/usr/bin/python3
"""Joins LinuxCNC's measured block times (lcnc_run.py JSON) with the program's blocks, for
comparing a timing model block by block.

  lcnc_blocks.py RESULT.json [--csv OUT.csv] [--accel MM_S2]

Per motion block: line, X Y Z A B end point, F, XYZ length L, |dA|, |dB|, measured time, and
sqrt(2 L / a) (the time to cover L from rest at acceleration a, the machine's XYZ acceleration
by default). Prints the correlation of measured time with sqrt(2 L / a) and with |dA|, and how
many blocks the planner brought to a stop (velocity 0 inside the block).
"""

import argparse
import csv
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gcode_blocks import parse_blocks  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result")
    parser.add_argument("--csv")
    parser.add_argument("--accel", type=float)
    args = parser.parse_args()
    with open(args.result) as f:
        result = json.load(f)
    with open(result["machine"]) as f:
        machine = json.load(f)
    accel = args.accel or min(machine["axes"][c]["acceleration_mm_s2"] for c in "XYZ")
    timed = {e["line"]: e for e in result["per_block"]}
    rows, prev = [], None
    for b in parse_blocks(result["program"]):
        if prev is not None and b["line"] in timed:
            length = math.dist([b[c] for c in "xyz"], [prev[c] for c in "xyz"])
            e = timed[b["line"]]
            rows.append({
                "line": b["line"], **{c: b[c] for c in "xyzab"}, "f": b["f"],
                "length_mm": length, "da_deg": abs(b["a"] - prev["a"]),
                "db_deg": abs(b["b"] - prev["b"]), "time_s": e["time_s"],
                "sqrt_2l_over_a": math.sqrt(2 * length / accel),
                "min_vel": e["min_vel"], "peak_vel": e["peak_vel"],
            })
        prev = b
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
    t = np.array([r["time_s"] for r in rows])
    root = np.array([r["sqrt_2l_over_a"] for r in rows])
    da = np.array([r["da_deg"] for r in rows])
    stops = sum(1 for r in rows if r["min_vel"] < 1e-6)
    print(f"{os.path.basename(result['program'])}: {len(rows)} blocks, time {t.sum():.3f} s, "
          f"median block {np.median(t) * 1000:.1f} ms; corr(t, sqrt(2L/a)) "
          f"{np.corrcoef(t, root)[0, 1]:.3f}, corr(t, |dA|) {np.corrcoef(t, da)[0, 1]:.3f}; "
          f"median t/sqrt(2L/a) {np.median(t / np.maximum(root, 1e-9)):.2f}; "
          f"{stops} blocks reach velocity 0")
    return 0


if __name__ == "__main__":
    sys.exit(main())
