#!/usr/bin/env bash
# Builds the Debian packages of a build with CPack and checks them as a user's dpkg would see
# them: file lists, control fields, copyright and changelogs, maintainer scripts, stripped and
# hardened binaries, the desktop entry, the manual page. Run as root (CI), it also installs the
# package, runs the installed program and removes it again. The packages stay in OUT_DIR for
# package.lintian.
# Usage: check_deb.sh BUILD_DIR VERSION OUT_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
version=$2
out=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() {
    echo "check_deb: $*" >&2
    exit 1
}

rm -rf "$out"
mkdir -p "$out"
(cd "$work" && cpack --config "$build/CPackConfig.cmake" -G DEB >cpack.log 2>&1) ||
    { cat "$work/cpack.log"; fail "cpack failed"; }
# <upstream version>-<Debian revision>: a non-native package, whose Debian changelog is
# changelog.Debian.gz (packaging/debian/changelog).
deb=$(compgen -G "$work/bladeaxis_${version}-*_amd64.deb") ||
    fail "expected bladeaxis_${version}-<revision>_amd64.deb, got: $(ls "$work")"
dev=$(compgen -G "$work/bladeaxis-dev_${version}-*_amd64.deb") ||
    fail "expected bladeaxis-dev_${version}-<revision>_amd64.deb"
debian_version=$(dpkg-deb -f "$deb" Version)
[[ $debian_version =~ ^${version//./\\.}-[0-9]+$ ]] || fail "Version $debian_version"
cp "$deb" "$dev" "$out/"

# Control fields: the name, version and architecture dpkg shows, the home page, and library
# dependencies worked out by dpkg-shlibdeps (Qt, VTK and OpenCASCADE at least).
info=$(dpkg-deb -I "$deb")
! grep -q ";" <<<"$(dpkg-deb -f "$deb" Description)" || fail "Description holds a CMake list separator"
for field in "Package: bladeaxis" "Version: $debian_version" "Architecture: amd64" \
    "Section: science" "Homepage: https://bladeaxis.example.org"; do
    grep -q "^ $field\$" <<<"$info" || fail "control field '$field' missing:"$'\n'"$info"
done
[[ $(dpkg-deb -f "$dev" Homepage) == https://* ]] || fail "$(basename "$dev") has no Homepage"
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
# The development files in Debian's multiarch folder, where the CMake package is found too.
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
dev_contents=$(dpkg-deb -c "$dev" | awk '{print $6}')
for file in ./usr/include/bladeaxis/bladeaxis.h \
    ./usr/lib/$multiarch/cmake/BladeAxis/BladeAxisConfig.cmake \
    ./usr/lib/$multiarch/libbladeaxis_api.a; do
    grep -qx "$file" <<<"$dev_contents" || fail "$(basename "$dev") lacks $file"
done
! grep -qE '^\./usr/lib/[^/]*\.a$|^\./usr/lib/cmake/' <<<"$dev_contents" ||
    fail "$(basename "$dev") has libraries outside /usr/lib/$multiarch"

# Both packages carry the machine-readable copyright file and both changelogs (Debian policy
# 12.5, 12.7); only the application has maintainer scripts (the desktop registration).
for package in "$deb" "$dev"; do
    name=$(dpkg-deb -f "$package" Package)
    files=$(dpkg-deb -c "$package" | awk '{print $6}')
    for file in copyright changelog.Debian.gz changelog.gz; do
        grep -qx "./usr/share/doc/$name/$file" <<<"$files" || fail "$name lacks /usr/share/doc/$name/$file"
    done
done
dpkg-deb -x "$dev" "$work/dev"
head -1 "$work/dev/usr/share/doc/bladeaxis-dev/copyright" |
    grep -qx 'Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/' ||
    fail "copyright is not in the machine-readable format"
zcat "$work/dev/usr/share/doc/bladeaxis-dev/changelog.Debian.gz" | head -1 |
    grep -q "^bladeaxis ($debian_version) " || fail "changelog.Debian.gz is not for $debian_version"
dpkg-deb -e "$dev" "$work/dev-control"
for script in preinst postinst prerm postrm; do
    [[ ! -e $work/dev-control/$script ]] || fail "$(basename "$dev") has a $script"
done

dpkg-deb -x "$deb" "$work/root"
# Stripped and hardened (packaging/CMakeLists.txt, cmake/BladeAxisHelpers.cmake): no symbol
# table, position-independent, full RELRO (read-only relocations, bound at start), the
# stack protector and the fortified string and memory functions.
elf_files=("$work/root/usr/bin/bladeaxis")
if [[ -n $python_module ]]; then
    elf_files+=("$(compgen -G "$work/root/usr/lib/python3/dist-packages/bladeaxis.cpython-*.so")")
fi
for elf in "${elf_files[@]}"; do
    name=${elf#"$work/root"}
    ! readelf -S "$elf" | grep -q '\.symtab' || fail "$name is not stripped"
    readelf -h "$elf" | grep -q 'Type: *DYN' || fail "$name is not position-independent"
    readelf -lW "$elf" | grep -q GNU_RELRO || fail "$name has no RELRO segment"
    readelf -dW "$elf" | grep -qE 'BIND_NOW|FLAGS.*NOW' || fail "$name is not linked with -z now"
    symbols=$(readelf --dyn-syms -W "$elf")
    grep -q '__stack_chk_fail' <<<"$symbols" || fail "$name has no stack protector"
    grep -qE '__[a-z]+_chk@' <<<"$symbols" || fail "$name calls no fortified function"
done
readelf -dW "$work/root/usr/bin/bladeaxis" | grep -q 'FLAGS_1.*PIE' || fail "/usr/bin/bladeaxis is no PIE"

# The files a desktop and man read are valid.
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
