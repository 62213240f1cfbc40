#!/usr/bin/env bash
# Fails when a library of the project defines the global operator new or delete. A plug-in links
# the core's archives (bladeaxis-dev) into a CAM host, and the Python module is loaded into an
# interpreter: a replacement there would become the host's allocator. Only the executable may
# set an allocator policy (app/memory).
#
# Usage: check_no_allocator.sh [--installed-from BUILD_DIR] [FILE...]
#   --installed-from  installs BUILD_DIR's development component (bladeaxis-dev) into a
#                     temporary prefix and checks every static archive installed there
#   FILE              a further archive or shared object to check (the Python module)
set -euo pipefail

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
files=()
if [[ ${1:-} == --installed-from ]]; then
    cmake --install "$2" --prefix "$work/prefix" --component development >"$work/install.log" ||
        { cat "$work/install.log"; exit 1; }
    mapfile -t files < <(find "$work/prefix" -name 'lib*.a' | sort)
    [[ ${#files[@]} -gt 0 ]] || { echo "no archive was installed from $2" >&2; exit 1; }
    shift 2
fi
files+=("$@")
[[ ${#files[@]} -gt 0 ]] || { echo "usage: $0 [--installed-from BUILD_DIR] [FILE...]" >&2; exit 2; }

# The replaceable forms ([new.delete]): single and array, sized, aligned and nothrow. Placement
# new (_ZnwmPv) is not replaceable and is not matched.
replaceable='^_Z(n[wa][mj](St11align_val_t)?(RKSt9nothrow_t)?|d[la]Pv[mj]?(St11align_val_t)?(RKSt9nothrow_t)?)$'
found=0
for file in "${files[@]}"; do
    # -A -P: "archive[member]: symbol type value size", one line per defined symbol, local
    # ones too (a module's hidden replacement still serves its own allocations). A file nm
    # cannot read fails the check rather than passing unread.
    symbols=$(nm -A -P --defined-only "$file") || { echo "nm cannot read $file" >&2; exit 1; }
    definitions=$(awk -v re="$replaceable" '$2 ~ re { print $1, $2 }' <<<"$symbols")
    if [[ -n $definitions ]]; then
        echo "$(basename "$file") defines operator new or delete:" >&2
        echo "$definitions" >&2
        found=1
    fi
done
[[ $found -eq 0 ]] || exit 1
echo "checked ${#files[@]} files: none defines operator new or delete"
