#!/usr/bin/env bash
# Debian's policy checker on the packages that package.deb built: fails on any error, and on a
# warning that packaging/lintian-accepted.txt does not list with its reason. An accepted entry
# that lintian no longer reports fails too, so the list cannot outlive its warnings.
# Information tags (I:) are printed, not judged.
# Usage: check_lintian.sh DEB_DIR SOURCE_DIR
set -euo pipefail
debs_dir=$1
source=$2
accepted_file=$source/packaging/lintian-accepted.txt

fail() {
    echo "check_lintian: $*" >&2
    exit 1
}
command -v lintian >/dev/null || fail "lintian missing (packaging/install-deps.sh installs it)"
mapfile -t debs < <(compgen -G "$debs_dir/*.deb" || true)
((${#debs[@]} == 2)) || fail "expected the two packages of package.deb in $debs_dir, got ${#debs[@]}"

# Accepted warnings: "<package> <tag> [context]  # reason", one a line; the reason is required.
declare -A accepted=()
if [[ -f $accepted_file ]]; then
    while IFS= read -r line; do
        [[ $line =~ ^[[:space:]]*(#|$) ]] && continue
        [[ $line == *"#"* && -n ${line#*#} ]] || fail "no reason given in $accepted_file: $line"
        entry=$(sed -E 's/[[:space:]]*#.*$//; s/[[:space:]]+/ /g' <<<"$line")
        accepted[$entry]=0
    done <"$accepted_file"
fi

# Root may run lintian (CI does); it says so on standard error, which is kept out of the tags.
output=$(lintian --display-level '>=info' --tag-display-limit 0 "${debs[@]}" 2>"$debs_dir/lintian.err") ||
    true
grep -v 'running with root privileges' "$debs_dir/lintian.err" >&2 || true
echo "$output"

failures=()
while IFS= read -r line; do
    # "E: package: tag [context]" or "W: package: tag [context]"
    [[ $line =~ ^([EW]):\ ([^:]+):\ ([^ ]+)(\ (.*))?$ ]] || continue
    level=${BASH_REMATCH[1]}
    entry="${BASH_REMATCH[2]} ${BASH_REMATCH[3]}"
    [[ -n ${BASH_REMATCH[5]} ]] && with_context="$entry ${BASH_REMATCH[5]}" || with_context=$entry
    if [[ $level == W && -v accepted[$with_context] ]]; then
        accepted[$with_context]=1
    elif [[ $level == W && -v accepted[$entry] ]]; then
        accepted[$entry]=1
    else
        failures+=("$line")
    fi
done <<<"$output"
for entry in "${!accepted[@]}"; do
    ((accepted[$entry] == 1)) || failures+=("accepted in lintian-accepted.txt but not reported: $entry")
done
if ((${#failures[@]} > 0)); then
    printf 'check_lintian: %s\n' "${failures[@]}" >&2
    fail "${#failures[@]} error(s) or unaccepted warning(s)"
fi
echo "check_lintian: $(basename -a "${debs[@]}" | tr '\n' ' ')- no error, every warning accepted with its reason"
