#!/usr/bin/env bash
# Writes the programs of `make controller-check` into OUT_DIR and prints their paths: the demo
# (original and re-scheduled) and a generated family of eight blades, two of each profile with
# different lead angle, pitch, tilt and chordal tolerance, each re-scheduled. The family members
# are two revolutions long to keep the real-time planner runs to about half a minute each; the
# demo keeps its full length. Every re-scheduling writes its report.json beside the program
# (<name>_report/), whose cycle-time models results_table.py sets beside the planner's times.
#
#   make_programs.sh BLADEAXIS OUT_DIR
set -euo pipefail
bin=$1
out=$2
mkdir -p "$out/demo" "$out/family"
"$bin" --batch --demo --out "$out/demo" -o "$out/demo/demo_blade_rescheduled.nc" >/dev/null
echo "$out/demo/demo_blade.nc"
echo "$out/demo/demo_blade_rescheduled.nc"
# profile lead_deg pitch_mm tilt_deg tolerance_mm
family=(
    "naca-high-camber 15 0.5 5 0.005"
    "naca-high-camber 10 1.0 5 0.002"
    "naca-weak 15 0.5 5 0.005"
    "naca-weak 20 1.5 10 0.005"
    "symmetric 15 0.5 5 0.005"
    "symmetric 12 1.0 0 0.003"
    "turbine 15 0.5 5 0.005"
    "turbine 20 1.0 8 0.005"
)
member=0
for parameters in "${family[@]}"; do
    read -r profile lead pitch tilt tolerance <<<"$parameters"
    member=$((member + 1))
    name=$out/family/m${member}_${profile}
    "$bin" generate "$name.nc" --profile "$profile" --revolutions 2 --lead-deg "$lead" \
        --pitch "$pitch" --tilt-deg "$tilt" --tolerance "$tolerance" >/dev/null
    "$bin" reschedule "$name.nc" -o "${name}_rescheduled.nc" --out "${name}_report" >/dev/null
    echo "$name.nc"
    echo "${name}_rescheduled.nc"
done
