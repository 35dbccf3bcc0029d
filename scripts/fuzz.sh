#!/usr/bin/env bash
# Runs the libFuzzer targets of BUILD/fuzz (tests/fuzz; `make sanitize-build` builds them) and prints
# one line per target: executions, seconds, executions per second, result.
#   FUZZ_SECONDS [60]   time per target
#   FUZZ_RUNS    [-1]   stop a target after this many executions instead (-1: no bound)
#   FUZZ_JOBS    [nproc] targets run at once
#   FUZZ_TARGETS [all]  space-separated names (problem_yaml png ...)
#   FUZZ_SEED    [0]    libFuzzer's -seed (0: drawn per run; CI fixes it so that a run repeats)
# A target fails on a crash, an uncaught non-amp exception, a leak (but assimp's own: tests/fuzz/
# lsan.supp), undefined behaviour, an input
# that runs over 1 s, or allocates over 2 GB. The seed corpus tests/fuzz/corpus/<name> is only read: new
# inputs, logs and failing inputs go to BUILD/fuzz-work/<name>/.
set -euo pipefail
build=${1:-build-sanitize}
src=$(cd "$(dirname "$0")/.." && pwd)
seconds=${FUZZ_SECONDS:-60}
runs=${FUZZ_RUNS:--1}
jobs=${FUZZ_JOBS:-$(nproc)}
targets=${FUZZ_TARGETS:-$(cd "$src/tests/fuzz" && ls ./*_fuzz.cpp | sed 's|^\./||; s|_fuzz\.cpp$||')}
work=$build/fuzz-work
symbolizer=$(command -v llvm-symbolizer-14 || command -v llvm-symbolizer || true)

run_one() {
  local name=$1 dir=$work/$1
  rm -rf "$dir" && mkdir -p "$dir/corpus"
  # Over 2 GB in one allocation fails every target. The total stays at 2 GB but for the mesh targets:
  # assimp 5.2 leaks about 2.4 kB per malformed STL or COLLADA file (tests/fuzz/lsan.supp), which
  # adds up to 2 GB within 10^6 executions without any one input needing much.
  local rss=2048
  case $name in mesh_*) rss=8192 ;; esac
  local dict=()
  [ -f "$src/tests/fuzz/dict/$name.dict" ] && dict=(-dict="$src/tests/fuzz/dict/$name.dict")
  if ASAN_OPTIONS=detect_leaks=1${symbolizer:+:external_symbolizer_path=$symbolizer} \
     LSAN_OPTIONS=suppressions=$src/tests/fuzz/lsan.supp UBSAN_OPTIONS=print_stacktrace=1 \
     "$build/fuzz/fuzz_$name" "$dir/corpus" "$src/tests/fuzz/corpus/$name" "${dict[@]}" \
       -max_total_time="$seconds" -runs="$runs" -seed="${FUZZ_SEED:-0}" -timeout=1 -malloc_limit_mb=2048 -rss_limit_mb="$rss" \
       -artifact_prefix="$dir/" -print_final_stats=1 >"$dir/log" 2>&1; then
    echo ok >"$dir/result"
  else
    echo FAILED >"$dir/result"
  fi
}

mkdir -p "$work"
running=0
for name in $targets; do
  [ -x "$build/fuzz/fuzz_$name" ] || { echo "fuzz: no target $build/fuzz/fuzz_$name (make sanitize-build)" >&2; exit 2; }
  run_one "$name" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n || true; running=$((running - 1)); fi
done
wait

failed=0
printf '%-16s %12s %8s %10s  %s\n' target executions seconds exec/s result
for name in $targets; do
  dir=$work/$name
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -1)
  secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$dir/log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$dir/log" | tail -1)
  result=$(cat "$dir/result")
  printf '%-16s %12s %8s %10s  %s\n' "$name" "${execs:-?}" "${secs:-?}" "${rate:-?}" "$result"
  if [ "$result" != ok ]; then
    failed=1
    echo "--- $name: $dir/log (failing input: $(ls "$dir"/crash-* "$dir"/leak-* "$dir"/timeout-* "$dir"/oom-* 2>/dev/null | head -1))"
    grep -m1 -E 'ERROR: |runtime error|amp fuzz:|terminate called|==[0-9]+==' "$dir/log" || tail -5 "$dir/log"
  fi
done
exit $failed
