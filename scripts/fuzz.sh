#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, FG_FUZZ=ON, in $FG_BUILD_DIR-fuzz) and runs each for SECONDS
# (default 600) on its corpus, kept in the fuzz build folder between runs, and the committed seeds
# in tests/fuzz/corpus/. Ends with a table of executions and corpus sizes per fuzzer (docs/testing.md).
# A crash stops it with exit 1; the reproducer stays in the fuzz build folder.
#   bash scripts/fuzz.sh [SECONDS]     scripts/fractograph.sh test runs it with 60
# Packages: scripts/fractograph.sh installs clang and libclang-rt-14-dev (TEST_PACKAGES).
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
FUZZ=${FG_BUILD_DIR:-$ROOT/build}-fuzz
JOBS=${FG_JOBS:-$(nproc)}
SECONDS_EACH=${1:-600}
FUZZERS=(fuzz_graph_loader fuzz_pack_reader fuzz_compiler fuzz_mandelbulber_import)

if [ ! -f "$FUZZ/build.ninja" ]; then
  # -O1 -g1, as the sanitizer build: libFuzzer's reports still name file and line, and it builds faster.
  # ccache, as scripts/fractograph.sh builds: a clone on a machine that fuzzed before recompiles what changed.
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  CCACHE_BASEDIR=$ROOT CCACHE_NOHASHDIR=1 CC=clang CXX=clang++ cmake -S "$ROOT" -B "$FUZZ" -G Ninja -DFG_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" "${launcher[@]}" >/dev/null
fi
echo "building the fuzzers (log: $FUZZ/build.log)"
CCACHE_BASEDIR=$ROOT CCACHE_NOHASHDIR=1 cmake --build "$FUZZ" -j "$JOBS" >"$FUZZ/build.log" 2>&1 || { tail -60 "$FUZZ/build.log"; exit 1; }

count() { find "$1" -type f 2>/dev/null | wc -l; }
rows=()
# The fuzzers run side by side (each is one process, one thread): the minute each is a minute of
# wall time for all of them, not one after another.
declare -A before pid
for target in "${FUZZERS[@]}"; do
  corpus=$FUZZ/corpus/$target log=$FUZZ/$target.log
  mkdir -p "$corpus"
  before[$target]=$(count "$corpus")
  echo "fuzzing $target for ${SECONDS_EACH}s (log: $log)"
  # -timeout: one compile of a strange graph under ASan takes seconds, not minutes.
  "$FUZZ/tests/fuzz/$target" -max_total_time="$SECONDS_EACH" -print_final_stats=1 -close_fd_mask=3 -timeout=120 \
    -rss_limit_mb=4096 -artifact_prefix="$FUZZ/$target-" "$corpus" "$ROOT/tests/fuzz/corpus/${target#fuzz_}" >"$log" 2>&1 &
  pid[$target]=$!
done
for target in "${FUZZERS[@]}"; do
  log=$FUZZ/$target.log
  if ! wait "${pid[$target]}"; then
    tail -60 "$log"; echo "$target found a crash (reproducer: $FUZZ/$target-crash-*)"; kill "${pid[@]}" 2>/dev/null; exit 1
  fi
  runs=$(grep -oE '^stat::number_of_executed_units: [0-9]+' "$log" | grep -oE '[0-9]+$')
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+$')
  rows+=("| $target | ${SECONDS_EACH} s | $runs | $((runs / SECONDS_EACH)) | ${before[$target]} -> $(count "$FUZZ/corpus/$target") | $cov |")
done
printf '\n| fuzzer | time | executions | per second | corpus (inputs, before -> after) | coverage (edges) |\n'
printf '|---|---|---|---|---|---|\n'
printf '%s\n' "${rows[@]}"
