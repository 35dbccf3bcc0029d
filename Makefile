# AMP — set-up and everyday commands. `make demo` and `make test` work on a bare Debian 12 machine.
BUILD     ?= build
SAN_BUILD ?= build-sanitize
JOBS      ?= $(shell nproc)
DEMO_OUT  ?= out/demo

.PHONY: all deps build demo test bench sanitize sanitize-build fuzz install-check clean

all: build

# `make test` also installs the test-only packages (OMPL for tests/oracle); `make demo` does not.
deps:
	@bash scripts/install-deps.sh $(DEPS_FLAGS)

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j$(JOBS)

demo: build
	./$(BUILD)/bin/amp demo --out $(DEMO_OUT)

test: DEPS_FLAGS = --test
test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

# `cmake --install` into a temporary prefix: every installed header compiles alone, and
# examples/plan_a_problem builds against find_package(amp) and solves a problem.
install-check: build
	@bash scripts/check-install.sh $(BUILD)

bench: build
	@for b in $(BUILD)/benchmarks/*_bench; do echo "== $$b"; $$b --benchmark_min_time=0.2 || exit 1; done

# AddressSanitizer + UndefinedBehaviorSanitizer build at -O1 with line tables (ASan's recommended
# level: the suite runs in minutes instead of the -O0 build's twenty, and reports keep file and
# line), with clang 14 so that the same libraries carry libFuzzer's coverage and serve `make fuzz`.
# `make sanitize` runs every test but the MPI one, whose leak reports come from inside Open MPI.
sanitize-build: DEPS_FLAGS = --sanitize
sanitize-build: deps
	@cmake -S . -B $(SAN_BUILD) -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Debug \
	  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DAMP_FUZZ=ON -DAMP_BUILD_BENCHMARKS=OFF -DAMP_BUILD_PYTHON=OFF >/dev/null
	@cmake --build $(SAN_BUILD) -j$(JOBS)

sanitize: sanitize-build
	cd $(SAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j$(JOBS) -E '^apps[.]mpi_bench_equals_single_process$$'

# Every libFuzzer target (tests/fuzz) for FUZZ_SECONDS each, FUZZ_JOBS at a time; FUZZ_RUNS bounds
# the executions instead (scripts/fuzz.sh).
FUZZ_SECONDS ?= 60
fuzz: sanitize-build
	@FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_SEED=$(FUZZ_SEED) FUZZ_TARGETS="$(FUZZ_TARGETS)" bash scripts/fuzz.sh $(SAN_BUILD)

clean:
	rm -rf $(BUILD) $(SAN_BUILD)
