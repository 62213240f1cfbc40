#!/usr/bin/env bash
# `make fuzz`: builds the libFuzzer targets (tests/fuzz) with clang 16, AddressSanitizer and
# UBSan in build/fuzz, and runs each for FUZZ_SECONDS (default 300) on its kept corpus and the
# test data. New coverage goes to out/fuzz/<target>/ (add what is worth keeping to
# tests/fuzz/corpus/<target>/); a crash, hang or internal error leaves its input in
# out/fuzz/findings/<target>/ and makes this script fail. Run as root or with sudo rights the
# first time (it installs clang-16 and its libFuzzer).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-300}"
targets=(${FUZZ_TARGETS:-program gcode apt point_table machine_file job_file})

need=()
for p in clang-16 libclang-rt-16-dev; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || need+=("$p")
done
if ((${#need[@]} > 0)); then
    SUDO=""
    if [[ $(id -u) -ne 0 ]]; then SUDO=sudo; fi
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}"
fi

# libstdc++ 12 hides <expected> from compilers that do not announce C++20 concepts in full;
# clang 16 implements what it needs (P0848) but announces 201907, so the fuzz build says so.
cmake -S . -B build/fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang-16 -DCMAKE_CXX_COMPILER=clang++-16 -DBLADEAXIS_FUZZ=ON \
    -DBLADEAXIS_BUILD_BENCHMARKS=OFF \
    "-DCMAKE_CXX_FLAGS=-Wno-macro-redefined -D__cpp_concepts=202002L" >/dev/null
cmake --build build/fuzz -j "$(nproc)" --target "${targets[@]/#/fuzz_}"

data=tests/data
seeds() {
    case "$1" in
    program)
        echo "tests/fuzz/corpus/gcode tests/fuzz/corpus/apt tests/fuzz/corpus/point_table" \
            "$data/nc $data/cl $data/awkward $data/bad $data/programs $data/dialects"
        ;;
    gcode) echo "$data/nc $data/bad/nc $data/awkward $data/dialects" ;;
    apt) echo "$data/cl $data/bad/cl $data/awkward" ;;
    point_table) echo "$data/awkward" ;;
    machine_file) echo "resources/machines $data/machines" ;;
    job_file) echo "" ;;
    esac
}

failed=0
for target in "${targets[@]}"; do
    mkdir -p "out/fuzz/$target" "out/fuzz/findings/$target"
    echo "== fuzz_$target for ${seconds} s"
    # shellcheck disable=SC2046
    if ! build/fuzz/tests/fuzz/fuzz_"$target" -max_total_time="$seconds" -max_len=8192 \
        -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
        -artifact_prefix="out/fuzz/findings/$target/" \
        "out/fuzz/$target" "tests/fuzz/corpus/$target" $(seeds "$target") \
        2>"out/fuzz/$target.log"; then
        echo "   finding: see out/fuzz/findings/$target/ and out/fuzz/$target.log"
        failed=1
    fi
    grep -E "stat::number_of_executed_units|stat::average_exec_per_sec" "out/fuzz/$target.log" |
        sed 's/^/   /'
done
exit "$failed"
