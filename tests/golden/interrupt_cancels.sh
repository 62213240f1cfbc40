#!/usr/bin/env bash
# Ctrl+C during a batch job: exit code 7, and neither the program nor the report folder written;
# SIGTERM during generation: exit code 7 and no program.
# Usage: interrupt_cancels.sh BLADEAXIS WORKDIR
set -uo pipefail
bladeaxis="$1"
work="$2"
rm -rf "$work" && mkdir -p "$work"

# Waits until process $1 catches signal number $2 (its SigCgt mask in /proc): a signal sent
# before then finds the inherited disposition (a background job of a script ignores SIGINT), not
# BladeAxis's handler, and loading the libraries can take longer than any fixed sleep on a
# loaded machine.
wait_for_handler() {
    local pid="$1" bit=$((1 << ($2 - 1))) mask
    for _ in $(seq 300); do
        mask=$(awk '/^SigCgt:/ {print $2}' "/proc/$pid/status" 2>/dev/null) || return 1
        [[ -n "$mask" ]] && (( 16#$mask & bit )) && return 0
        sleep 0.1
    done
    echo "process $pid never caught signal $2"
    return 1
}
"$bladeaxis" --batch --generate "$work/long.nc" --revolutions 90 --pitch 0.2 >/dev/null || exit 1
"$bladeaxis" --batch "$work/long.nc" --tool-radius 8 --compare -q \
    -o "$work/out.nc" --out "$work/report" 2>"$work/stderr.txt" &
job=$!
wait_for_handler "$job" 2 || exit 1
sleep 0.3
kill -INT "$job"
wait "$job"
code=$?
if [[ $code -ne 7 ]]; then
    echo "expected exit code 7 after SIGINT, got $code: $(cat "$work/stderr.txt")"
    exit 1
fi
if [[ -e "$work/out.nc" || -e "$work/report" ]]; then
    echo "an interrupted job wrote outputs: $(ls "$work")"
    exit 1
fi
grep -q "interrupted: nothing was written" "$work/stderr.txt" || { cat "$work/stderr.txt"; exit 1; }
# SIGTERM while a program is generated ended the process by the signal (143): it is a cancel too.
"$bladeaxis" --batch --generate "$work/generated.nc" --revolutions 30 --pitch 0.5 -q \
    2>"$work/generate_stderr.txt" &
generate=$!
wait_for_handler "$generate" 15 || exit 1
kill -TERM "$generate"
wait "$generate"
code=$?
if [[ $code -ne 7 || -e "$work/generated.nc" ]]; then
    echo "expected exit code 7 and no program after SIGTERM during generation, got $code:" \
        "$(cat "$work/generate_stderr.txt"; ls "$work")"
    exit 1
fi
echo "interrupted job and generation exited 7 and wrote nothing"
