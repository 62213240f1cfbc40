#!/usr/bin/env bash
# Runs G-code programs through LinuxCNC's real trajectory planner (headless, real time, one
# LinuxCNC at a time) and tabulates the planner's cycle time of each.
#
#   controller_check.sh MACHINE.json OUT_DIR PROGRAM...
#
# Per program OUT_DIR/<name>.json holds the cycle time (first to last servo period with motion),
# the block count and the time of every block (lcnc_run.py); OUT_DIR/summary.csv has one row per
# program: program, variant (original, or rescheduled for names ending in _rescheduled), blocks,
# planner time. Set LCNC_STARTUP to change the RS274NGC startup code (default G64 P0.01; plain
# "G21 G90 G94 G64" blends without tolerance).
set -euo pipefail

if (($# < 3)); then
    sed -n '2,12p' "$0"
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
machine=$1
out=$2
shift 2
startup=${LCNC_STARTUP:-G21 G90 G94 G64 P0.01}
mkdir -p "$out"
summary=$out/summary.csv
echo "program,variant,blocks,planner_time_s,attempts" >"$summary"

status=0
for program in "$@"; do
    name=$(basename "$program")
    name=${name%.*}
    variant=original
    base=$name
    if [[ $name == *_rescheduled ]]; then
        variant=rescheduled
        base=${name%_rescheduled}
    fi
    if ! python3 "$here/lcnc_run.py" "$machine" "$program" "$out/$name.json" --startup "$startup"; then
        echo "controller-check: $program failed" >&2
        echo "$base,$variant,,failed," >>"$summary"
        status=1
        continue
    fi
    python3 - "$out/$name.json" "$base" "$variant" >>"$summary" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]},{sys.argv[3]},{d['blocks']},{d['cycle_time_s']:.3f},{d['attempts']}")
PY
done
echo "controller-check: $summary"
column -s, -t "$summary"
exit $status
