#!/usr/bin/env python3
"""Sets BladeAxis's cycle-time models beside LinuxCNC's planner, per program.

    results_table.py OUT_DIR

reads OUT_DIR/summary.csv (controller_check.sh) and the report.json of each re-scheduling
(make_programs.sh: demo/report.json, family/<name>_report/report.json) and prints a Markdown
table: the planner's time, the block-by-block model's, its error, the look-ahead T2 and T1, and
per program the planner's gain of the re-scheduled program over the original. Exits 1 when the
block-by-block model misses the planner by more than 10 % on any program.
"""

import csv
import json
import statistics
import sys
from pathlib import Path


def report_of(out: Path, base: str) -> dict:
    demo = out / "demo" / "report.json"
    if base == "demo_blade" and demo.exists():
        return json.loads(demo.read_text())
    return json.loads((out / "family" / f"{base}_report" / "report.json").read_text())


def models(report: dict, variant: str) -> dict:
    section = report["original"] if variant == "original" else report["rescheduled"]["analysis"]
    times = section["cycle_times"]
    return {
        "block": times["block_by_block"]["time_s"],
        "t2": times.get("look_ahead", {}).get("time_s"),
        "t1": times["constant_feed"]["time_s"],
    }


def main() -> int:
    out = Path(sys.argv[1])
    rows = list(csv.DictReader((out / "summary.csv").open()))
    planner = {(r["program"], r["variant"]): float(r["planner_time_s"]) for r in rows
               if r["planner_time_s"] not in ("", "failed")}
    print("| program | variant | LinuxCNC planner (s) | block-by-block model (s) | model error "
          "| look-ahead T2 (s) | T1 (s) |")
    print("|---|---|---|---|---|---|---|")
    worst = 0.0
    gains = {}
    for (program, variant), measured in planner.items():
        m = models(report_of(out, program), variant)
        error = (m["block"] - measured) / measured
        worst = max(worst, abs(error))
        t2 = f"{m['t2']:.1f}" if m["t2"] is not None else "-"
        print(f"| {program} | {variant} | {measured:.1f} | {m['block']:.1f} | {100 * error:+.1f} % "
              f"| {t2} | {m['t1']:.1f} |")
    for program in sorted({p for p, _ in planner}):
        if (program, "original") in planner and (program, "rescheduled") in planner:
            before, after = planner[(program, "original")], planner[(program, "rescheduled")]
            gains[program] = (before - after) / before
    print()
    print("| program | planner: re-scheduled vs original |")
    print("|---|---|")
    for program, gain in gains.items():
        print(f"| {program} | {100 * gain:+.1f} % faster |")
    family = [g for p, g in gains.items() if p != "demo_blade"]
    if family:
        print(f"\nfamily median: {100 * statistics.median(family):+.1f} % faster "
              f"({len(family)} programs); largest model error {100 * worst:.1f} %")
    return 1 if worst > 0.10 else 0


if __name__ == "__main__":
    sys.exit(main())
