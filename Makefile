# AMP — set-up and everyday commands. `make demo` and `make test` work on a bare Debian 12 machine.
BUILD     ?= build
SAN_BUILD ?= build-sanitize
JOBS      ?= $(shell nproc)
DEMO_OUT  ?= out/demo

# Ninja where it is installed (scripts/install-deps.sh installs it): it schedules the two cores
# better than make and logs each step's time (BUILD/.ninja_log). A tree already configured keeps
# its generator.
generator = $(if $(wildcard $(1)/CMakeCache.txt),,$(if $(shell command -v ninja 2>/dev/null),-G Ninja,))

.PHONY: all deps configure build demo test timing arms slow bench sanitize sanitize-build fuzz install-check clean

all: build

# `make test` also installs the test-only packages (OMPL for tests/oracle); `make demo` does not.
deps:
	@bash scripts/install-deps.sh $(DEPS_FLAGS)

configure: deps
	@cmake -S . -B $(BUILD) $(call generator,$(BUILD)) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

# The demo runs `amp` alone: build only it and the libraries it links, not the test suite, the
# benchmarks or the Python module (a bare machine's `make demo` took 16 minutes building those).
demo: configure
	@cmake --build $(BUILD) -j$(JOBS) --target amp_cli
	./$(BUILD)/bin/amp demo --out $(DEMO_OUT)

# The whole suite but the `timing` label: wall-clock promises, which a busy machine can break, run
# alone on an idle machine by `make timing` (CI does it after the suite).
test: DEPS_FLAGS = --test
test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) -LE '^(timing|arms|slow)$$'

timing: build
	cd $(BUILD) && ctest --output-on-failure -j1 -L '^timing$$'

# Every planner on the shared MotionBenchMaker arm problems, checked by an independent mesh oracle
# (tests/problems/arm_planners_test.cpp, about 4 minutes; needs ../shared/mbm).
arms: build
	cd $(BUILD) && ctest --output-on-failure -j1 -L '^arms$$'

# Checks too slow for every run: the SINS scale calibration reproduced from scratch
# (tests/bench/sins_scale_reproduction_test.cpp, about 5 minutes).
slow: build
	cd $(BUILD) && ctest --output-on-failure -j1 -L '^slow$$'

# `cmake --install` into a temporary prefix: every installed header compiles alone, and
# examples/plan_a_problem builds against find_package(amp) and solves a problem.
install-check: build
	@bash scripts/check-install.sh $(BUILD)

bench: build
	@for b in $(BUILD)/benchmarks/*_bench; do echo "== $$b"; $$b --benchmark_min_time=0.2 || exit 1; done

# AddressSanitizer + UndefinedBehaviorSanitizer build at -O1 with line tables (ASan's recommended
# level: the suite runs in minutes instead of the -O0 build's twenty, and reports keep file and
# line), with clang 14 so that the same libraries carry libFuzzer's coverage and serve `make fuzz`.
# `make sanitize` runs every test but the MPI one, whose leak reports come from inside Open MPI, the
# SINS calibration's full probe test (about 160 s here; `make test` runs it, and its code runs here
# through the calibration's three other tests), and the wall-clock `timing` label, the `arms` label
# (it skips itself there), `slow` and `browser` (the 3-D viewer in Chromium: JavaScript, whose
# C++ side runs here through tests/viz/viewer_page_test.cpp). The sphere model's
# tests share one generated cover per build (tests/support/sphere_test_cache.hpp), so they run here too.
sanitize-build: DEPS_FLAGS = --sanitize
sanitize-build: deps
	@cmake -S . -B $(SAN_BUILD) $(call generator,$(SAN_BUILD)) -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Debug \
	  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DAMP_FUZZ=ON -DAMP_BUILD_BENCHMARKS=OFF -DAMP_BUILD_PYTHON=OFF >/dev/null
	@cmake --build $(SAN_BUILD) -j$(JOBS)

sanitize: sanitize-build
	cd $(SAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j$(JOBS) -LE '^(timing|arms|slow|browser)$$' -E '^(apps[.]mpi_bench_equals_single_process|SinsCalibration[.]ProbesAndCheckEqualIndependentRuns)$$'

# Every libFuzzer target (tests/fuzz) for FUZZ_SECONDS each, FUZZ_JOBS at a time; FUZZ_RUNS bounds
# the executions instead (scripts/fuzz.sh).
FUZZ_SECONDS ?= 60
fuzz: sanitize-build
	@FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_SEED=$(FUZZ_SEED) FUZZ_TARGETS="$(FUZZ_TARGETS)" bash scripts/fuzz.sh $(SAN_BUILD)

clean:
	rm -rf $(BUILD) $(SAN_BUILD)
