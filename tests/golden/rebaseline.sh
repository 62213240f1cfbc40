#!/usr/bin/env bash
# Copies the actual outputs of golden cases over their expectations, after you have reviewed
# the differences. Usage: tests/golden/rebaseline.sh [build-dir] [case ...]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build/dev}"
shift || true
cases=("$@")
if ((${#cases[@]} == 0)); then
    mapfile -t cases < <(cd "$root/tests/golden" && ls -d */ | tr -d /)
fi
for case in "${cases[@]}"; do
    expect="$root/tests/golden/$case/expect"
    actual="$build/tests/golden/$case/out"
    for file in "$expect"/*.json "$expect"/*.csv; do
        [[ -e "$file" ]] || continue
        cp "$actual/$(basename "$file")" "$file"
        echo "rebaselined $case/$(basename "$file")"
    done
done
