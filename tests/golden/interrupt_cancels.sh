#!/usr/bin/env bash
# Ctrl+C during a batch job: exit code 7, and neither the program nor the report folder written;
# SIGTERM during generation: exit code 7 and no program.
# Usage: interrupt_cancels.sh BLADEAXIS WORKDIR
set -uo pipefail
bladeaxis="$1"
work="$2"
rm -rf "$work" && mkdir -p "$work"
"$bladeaxis" --batch --generate "$work/long.nc" --revolutions 90 --pitch 0.2 >/dev/null || exit 1
"$bladeaxis" --batch "$work/long.nc" --tool-radius 8 --compare -q \
    -o "$work/out.nc" --out "$work/report" 2>"$work/stderr.txt" &
job=$!
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
sleep 1 # the generation takes seconds; a signal before main() runs would be the system's
kill -TERM "$generate"
wait "$generate"
code=$?
if [[ $code -ne 7 || -e "$work/generated.nc" ]]; then
    echo "expected exit code 7 and no program after SIGTERM during generation, got $code:" \
        "$(cat "$work/generate_stderr.txt"; ls "$work")"
    exit 1
fi
echo "interrupted job and generation exited 7 and wrote nothing"
