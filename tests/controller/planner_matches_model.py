#!/usr/bin/env python3
"""LinuxCNC's real trajectory planner against BladeAxis's block-by-block cycle-time model.

    planner_matches_model.py --bladeaxis BIN --machine MACHINE.json --work DIR

Generates a short blade program (one revolution), re-schedules it, runs both through
LinuxCNC 2.9's planner in real time (lcnc_run.py) and requires the block-by-block model of
report.json to be within 10 % of the planner's time for each. A figure BladeAxis prints as
"LinuxCNC 2.9" is checked here against LinuxCNC itself.
"""

import argparse
import json
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
TOLERANCE = 0.10


def run(*command):
    subprocess.run([str(c) for c in command], check=True, stdout=subprocess.DEVNULL)


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--bladeaxis", required=True)
    parser.add_argument("--machine", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    work = Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    original = work / "blade.nc"
    rescheduled = work / "blade_rescheduled.nc"
    run(args.bladeaxis, "generate", original, "--profile", "naca-weak", "--revolutions", "1")
    run(args.bladeaxis, "reschedule", original, "--machine", args.machine, "-o", rescheduled,
        "--out", work / "report")
    report = json.loads((work / "report" / "report.json").read_text())
    model = {
        original: report["original"]["cycle_times"]["block_by_block"]["time_s"],
        rescheduled: report["rescheduled"]["analysis"]["cycle_times"]["block_by_block"]["time_s"],
    }
    passed = failed = 0
    for program, predicted in model.items():
        timing = work / (program.stem + ".json")
        # Debian's interpreter: the linuxcnc module is installed for it only.
        run("/usr/bin/python3", HERE / "lcnc_run.py", args.machine, program, timing)
        measured = json.loads(timing.read_text())["cycle_time_s"]
        error = (predicted - measured) / measured
        ok = abs(error) <= TOLERANCE
        print(f"{program.name}: planner {measured:.2f} s, block-by-block model {predicted:.2f} s "
              f"({100 * error:+.1f} %) {'ok' if ok else 'MORE THAN 10 % OFF'}")
        passed += ok
        failed += not ok
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
