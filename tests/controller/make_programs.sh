#!/usr/bin/env bash
# Writes the programs of `make controller-check` into OUT_DIR and prints their paths: the demo
# (original and re-scheduled) and a generated family of six blades over the four profiles, each
# re-scheduled. The family members are one revolution long (--revolutions 1) to keep the
# real-time planner runs to a few seconds each; the demo keeps its full length.
#
#   make_programs.sh BLADEAXIS OUT_DIR
set -euo pipefail
bin=$1
out=$2
mkdir -p "$out/demo" "$out/family"
"$bin" --batch --demo --out "$out/demo" -o "$out/demo/demo_blade_rescheduled.nc" >/dev/null
echo "$out/demo/demo_blade.nc"
echo "$out/demo/demo_blade_rescheduled.nc"
for member in naca-high-camber:1 naca-high-camber:2 naca-weak:3 symmetric:4 turbine:5 turbine:6; do
    profile=${member%:*}
    seed=${member#*:}
    name=$out/family/${profile}_s$seed
    "$bin" generate "$name.nc" --profile "$profile" --revolutions 1 --seed "$seed" >/dev/null
    "$bin" reschedule "$name.nc" --tool-radius 8 -o "${name}_rescheduled.nc" >/dev/null
    echo "$name.nc"
    echo "${name}_rescheduled.nc"
done
