#!/usr/bin/env bash
# Runs every benchmark executable of a build (make bench) and keeps the JSON results under
# out/bench/. Benchmarks are never part of `make test`: timings are reported, not asserted.
set -euo pipefail
build="${1:-build/dev}"
mkdir -p out/bench
found=0
for bench in "$build"/tests/bench/bench_*; do
    [[ -x "$bench" ]] || continue
    found=1
    name=$(basename "$bench")
    echo "== $name"
    runner=()
    if [[ "$name" == bench_view ]]; then
        # VTK renders only with an X display (docs/product.md): a private Xvfb when available.
        if command -v xvfb-run >/dev/null; then
            runner=(env QT_QPA_PLATFORM=xcb xvfb-run -a)
        elif [[ -z "${DISPLAY:-}" ]]; then
            echo "   skipped: needs xvfb-run or an X display"
            continue
        fi
    fi
    "${runner[@]}" "$bench" --benchmark_out="out/bench/$name.json" --benchmark_out_format=json \
             --benchmark_counters_tabular=true
done
if ((found == 0)); then
    echo "no benchmarks built in $build (configure with -DBLADEAXIS_BUILD_BENCHMARKS=ON)" >&2
    exit 1
fi
