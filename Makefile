# The two entry points of the README: `make demo` and `make test`. Both install what they need.
# Developers can use the CMake presets directly: cmake --preset dev && cmake --build --preset dev.

BUILD_DIR := build/dev
JOBS ?= $(shell nproc)

.PHONY: deps configure build demo test test-asan bench fuzz package format format-check clean controller-check

deps:
	bash packaging/install-deps.sh

configure: deps
	cmake --preset dev >/dev/null

build: configure
	cmake --build --preset dev -j $(JOBS)

demo: build
	$(BUILD_DIR)/app/bladeaxis --batch --demo --compare --out out/demo -o out/demo/demo_blade_rescheduled.nc

test: build
	ctest --preset dev -j $(JOBS)

# The unit, golden and fuzz-corpus tests built with AddressSanitizer and UBSan (preset asan);
# CI runs it after `make test` (docs/reliability.md).
test-asan: deps
	cmake --preset asan >/dev/null
	cmake --build --preset asan -j $(JOBS)
	ctest --preset asan -j $(JOBS)

# The demo and a generated family (original and re-scheduled) through LinuxCNC's real-time
# trajectory planner, headless: out/controller/summary.csv and one JSON of block times per
# program (tests/controller/controller_check.sh). Real time: several minutes.
controller-check: build
	mkdir -p out/controller
	bash tests/controller/make_programs.sh $(BUILD_DIR)/app/bladeaxis out/controller > out/controller/programs.txt
	bash tests/controller/controller_check.sh resources/machines/blade_ab.json out/controller $$(cat out/controller/programs.txt)
	python3 tests/controller/results_table.py out/controller

bench: build
	bash tests/bench/run_benchmarks.sh $(BUILD_DIR)

# The Debian packages bladeaxis_<version>_amd64.deb (the application) and bladeaxis-dev (the
# core as a CMake package for plug-ins), in $(BUILD_DIR); install with `apt install ./bladeaxis_*.deb`.
package: build
	cd $(BUILD_DIR) && cpack -G DEB

# libFuzzer on every reader for FUZZ_SECONDS each (default 300); see docs/reliability.md.
fuzz: deps
	bash packaging/fuzz.sh

format:
	find core app tests $$(test -d ui && echo ui) \( -path tests/data -o -path tests/fuzz/corpus \) -prune -o \( -name '*.h' -o -name '*.cpp' \) -print | xargs clang-format -i

clean:
	rm -rf build out
