#!/usr/bin/env bash
# Installs every Debian 12 package BladeAxis needs to build, test and run.
# Idempotent: when everything is present it only runs dpkg-query (well under a second).
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config git
    libeigen3-dev nlohmann-json3-dev libcli11-dev
    libgtest-dev libgmock-dev libbenchmark-dev libalglib-dev libglpk-dev
    qt6-base-dev qt6-charts-dev libgl-dev
    libvtk9-dev
    libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-visualization-dev
    xvfb xauth locales clang-format
    # packaging and its tests: dpkg-shlibdeps, desktop-entry check, manual-page rendering,
    # the Debian policy check of the packages, the desktop's MIME database as GLib and
    # xdg-mime (File::MimeInfo) read it
    dpkg-dev desktop-file-utils groff-base man-db lintian
    shared-mime-info libglib2.0-bin xdg-utils libfile-mimeinfo-perl
    # the Python module and the report.json schema check
    pybind11-dev python3-dev python3-numpy python3-pytest python3-jsonschema
    # LinuxCNC as a client of the written programs: rs274 in make test, the planner in make controller-check
    linuxcnc-uspace
    # FreeCAD 0.20 (its CAM/Path workbench) for the FreeCAD plug-in's test, run in freecadcmd
    freecad
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if ((${#missing[@]} > 0)); then
    echo "install-deps: installing ${missing[*]}"
    SUDO=""
    if [[ $(id -u) -ne 0 ]]; then SUDO=sudo; fi
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# A decimal-comma locale for the locale-independence tests.
if ! locale -a 2>/dev/null | grep -qi '^de_DE.utf8$'; then
    SUDO=""
    if [[ $(id -u) -ne 0 ]]; then SUDO=sudo; fi
    $SUDO sed -i 's/^# *de_DE.UTF-8 UTF-8/de_DE.UTF-8 UTF-8/' /etc/locale.gen
    $SUDO locale-gen >/dev/null
fi
