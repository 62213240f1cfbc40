#!/usr/bin/env bash
# Installs the development component of a build into a temporary prefix, builds the consumer
# project (tests/package/consumer) against it with find_package(BladeAxis), and runs it.
# Usage: check_consumer.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" --component development >/dev/null
test -f "$work/prefix/include/bladeaxis/bladeaxis.h"
cmake -S "$source/tests/package/consumer" -B "$work/build" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/build" >"$work/build.log" || { cat "$work/build.log"; exit 1; }
mkdir -p "$work/out"
"$work/build/consumer" "$work/out"
