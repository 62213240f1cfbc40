#!/usr/bin/env bash
# The file types of packaging/bladeaxis-mime.xml as a desktop sees them: a MIME database made
# from the system's packages plus ours (update-mime-database on a scratch folder, the system's
# left alone), queried through GLib (gio: GNOME, Xfce) and xdg-mime (File::MimeInfo, the
# generic desktop). Job files are recognised by content whatever their name, .nc programs are
# G-code and NetCDF files stay NetCDF, and plain JSON stays JSON.
# Usage: check_mime.sh SOURCE_DIR
set -euo pipefail
source=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() {
    echo "check_mime: $*" >&2
    exit 1
}
for tool in update-mime-database gio xdg-mime mimetype; do
    command -v "$tool" >/dev/null || fail "$tool missing (packaging/install-deps.sh installs it)"
done

mkdir -p "$work/data/mime/packages" "$work/home" "$work/files"
cp /usr/share/mime/packages/*.xml "$work/data/mime/packages/"
cp "$source/packaging/bladeaxis-mime.xml" "$work/data/mime/packages/bladeaxis.xml"
update-mime-database "$work/data/mime" 2>"$work/update.log" || {
    cat "$work/update.log"
    fail "update-mime-database refused packaging/bladeaxis-mime.xml"
}
# Any complaint about our file (an unknown element, a bad magic value) fails too.
! grep -i bladeaxis "$work/update.log" || fail "update-mime-database warned about our file"

f=$work/files
# A job as BladeAxis saves it (core/job/job_file.cpp jobJsonText: "schema" first, then the
# rest), under a plain .json name, and one written by hand without blanks.
printf '{\n  "schema": "bladeaxis-job/1",\n  "program": "blade.nc",\n  "layer_edits": []\n}\n' >"$f/job.json"
printf '{"schema":"bladeaxis-job/1","program":"blade.nc"}\n' >"$f/compact job.json"
cp "$f/job.json" "$f/saved.bladeaxis.json"
printf '{\n  "name": "not a job",\n  "schema": "something-else/1"\n}\n' >"$f/plain.json"
# A posted program under .nc and the Sinumerik extension; NetCDF classic and NetCDF-4 (HDF5).
printf '%%\nO1000 (BLADE)\nG90 G21 G94\nG1 X10. Y0. Z5. A0. B15. F1200.\nM30\n%%\n' >"$f/blade.nc"
cp "$f/blade.nc" "$f/BLADE.MPF"
printf 'CDF\001\000\000\000\000\000\000\000\000\000\000\000\000' >"$f/climate.nc"
printf 'CDF\002\000\000\000\000\000\000\000\000\000\000\000\000' >"$f/climate64.nc"
printf '\211HDF\r\n\032\n\000\000\000\000\000\010\010\000\004\000\020\000' >"$f/climate4.nc"

expect=(
    "job.json=application/x-bladeaxis-job"
    "compact job.json=application/x-bladeaxis-job"
    "saved.bladeaxis.json=application/x-bladeaxis-job"
    "plain.json=application/json"
    "blade.nc=text/x.gcode"
    "BLADE.MPF=text/x.gcode"
    "climate.nc=application/x-netcdf"
    "climate64.nc=application/x-netcdf"
    "climate4.nc=application/x-netcdf"
)
export XDG_DATA_DIRS=$work/data XDG_DATA_HOME=$work/home XDG_CURRENT_DESKTOP=
failures=0
for entry in "${expect[@]}"; do
    name=${entry%%=*}
    want=${entry#*=}
    glib=$(gio info -a standard::content-type "$f/$name" | sed -n 's/^ *standard::content-type: //p')
    xdg=$(xdg-mime query filetype "$f/$name")
    echo "check_mime: $name: gio $glib, xdg-mime $xdg (expected $want)"
    if [[ $glib != "$want" || $xdg != "$want" ]]; then
        failures=$((failures + 1))
    fi
done
((failures == 0)) || fail "$failures file(s) recognised as another type"

# The desktop entry offers BladeAxis for both types; text/x-gcode is an alias of text/x.gcode.
grep -q '^MimeType=.*application/x-bladeaxis-job;' "$source/packaging/bladeaxis.desktop" ||
    fail "bladeaxis.desktop does not list application/x-bladeaxis-job"
grep -q '^MimeType=.*text/x\.gcode;' "$source/packaging/bladeaxis.desktop" ||
    fail "bladeaxis.desktop does not list text/x.gcode"
grep -qx 'text/x-gcode text/x.gcode' "$work/data/mime/aliases" || fail "text/x-gcode is no alias"
echo "check_mime: job files by content, G-code and NetCDF .nc files told apart"
