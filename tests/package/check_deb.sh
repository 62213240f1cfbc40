#!/usr/bin/env bash
# Builds the Debian packages of a build with CPack and checks them as a user's dpkg would see
# them: file lists, control fields, the desktop entry, the manual page. Run as root (CI), it also
# installs the package, runs the installed program and removes it again.
# Usage: check_deb.sh BUILD_DIR VERSION
set -euo pipefail
build=$(cd "$1" && pwd)
version=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() {
    echo "check_deb: $*" >&2
    exit 1
}

(cd "$work" && cpack --config "$build/CPackConfig.cmake" -G DEB >cpack.log 2>&1) ||
    { cat "$work/cpack.log"; fail "cpack failed"; }
deb=$work/bladeaxis_${version}_amd64.deb
dev=$work/bladeaxis-dev_${version}_amd64.deb
[[ -f $deb ]] || fail "expected $(basename "$deb"), got: $(ls "$work")"
[[ -f $dev ]] || fail "expected $(basename "$dev")"

# Control fields: the name, version and architecture dpkg shows, and library dependencies
# worked out by dpkg-shlibdeps (Qt, VTK and OpenCASCADE at least).
info=$(dpkg-deb -I "$deb")
! grep -q ";" <<<"$(dpkg-deb -f "$deb" Description)" || fail "Description holds a CMake list separator"
for field in "Package: bladeaxis" "Version: $version" "Architecture: amd64" "Section: science"; do
    grep -q "^ $field\$" <<<"$info" || fail "control field '$field' missing:"$'\n'"$info"
done
depends=$(dpkg-deb -f "$deb" Depends)
for library in libqt6widgets6 libvtk9 libocct-data-exchange libc6; do
    grep -q "$library" <<<"$depends" || fail "Depends lacks $library: $depends"
done

contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for file in ./usr/bin/bladeaxis ./usr/share/man/man1/bladeaxis.1.gz \
    ./usr/share/applications/bladeaxis.desktop ./usr/share/mime/packages/bladeaxis.xml \
    ./usr/share/icons/hicolor/scalable/apps/bladeaxis.svg \
    ./usr/share/bladeaxis/machines/blade_ab.json ./usr/share/doc/bladeaxis/README.md \
    ./usr/share/doc/bladeaxis/job-file.md; do
    grep -qx "$file" <<<"$contents" || fail "$(basename "$deb") lacks $file"
done
# The Python module, when the build has one (BLADEAXIS_PYTHON with pybind11 found).
python_module=$(compgen -G "$build/python/bladeaxis.cpython-*.so" || true)
if [[ -n $python_module ]]; then
    grep -qE '^\./usr/lib/python3/dist-packages/bladeaxis\.cpython-[^/]*\.so$' <<<"$contents" ||
        fail "$(basename "$deb") lacks ./usr/lib/python3/dist-packages/bladeaxis.cpython-*.so"
    grep -q "python3-numpy" <<<"$depends" || fail "Depends lacks python3-numpy: $depends"
fi
# The application package holds no headers or static libraries: they are bladeaxis-dev's.
! grep -qE '\.a$|/include/' <<<"$contents" || fail "$(basename "$deb") holds development files"
dev_contents=$(dpkg-deb -c "$dev" | awk '{print $6}')
for file in ./usr/include/bladeaxis/bladeaxis.h ./usr/lib/cmake/BladeAxis/BladeAxisConfig.cmake; do
    grep -q "^${file%/*}/.*${file##*/}\$" <<<"$dev_contents" || fail "$(basename "$dev") lacks $file"
done

# The files a desktop and man read are valid.
dpkg-deb -x "$deb" "$work/root"
if command -v desktop-file-validate >/dev/null; then
    desktop-file-validate "$work/root/usr/share/applications/bladeaxis.desktop"
fi
warnings=$(zcat "$work/root/usr/share/man/man1/bladeaxis.1.gz" | groff -man -Tutf8 -ww -z 2>&1)
[[ -z $warnings ]] || fail "manual page warnings: $warnings"
zcat "$work/root/usr/share/man/man1/bladeaxis.1.gz" | grep -qF 'tool\-radius' ||
    fail "manual page does not list --tool-radius"

if [[ $(id -u) -ne 0 ]] ||
    dpkg-query -W -f='${Status}' bladeaxis 2>/dev/null | grep -q 'install ok installed'; then
    echo "check_deb: not root, or bladeaxis already installed: install step skipped"
    exit 0
fi
trap 'dpkg -P bladeaxis >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
dpkg -i "$deb" >"$work/dpkg.log" 2>&1 || { cat "$work/dpkg.log"; fail "dpkg -i failed"; }
/usr/bin/bladeaxis --version | grep -q "bladeaxis $version" || fail "installed --version"
(cd "$work" && /usr/bin/bladeaxis --batch --demo --quiet --out demo \
    --machine /usr/share/bladeaxis/machines/blade_ab.json -o demo/demo_rescheduled.nc)
[[ -s $work/demo/report.json && -s $work/demo/demo_rescheduled.nc ]] || fail "installed demo"
man -w bladeaxis >/dev/null 2>&1 || fail "man bladeaxis does not find the page"
if [[ -n $python_module ]]; then
    # From outside the build tree, so that only the installed module can be imported.
    imported=$(cd "$work" && env -u PYTHONPATH /usr/bin/python3 -c \
        "import bladeaxis; print(bladeaxis.__version__)") || fail "installed module: import failed"
    [[ $imported == "$version" ]] || fail "installed module: version '$imported'"
fi
dpkg -P bladeaxis >/dev/null
[[ ! -e /usr/bin/bladeaxis ]] || fail "dpkg -P left /usr/bin/bladeaxis"
echo "check_deb: $(basename "$deb") and $(basename "$dev") built, checked, installed and removed"
