#!/usr/bin/env bash
# Fuzzes the scene parser and scene building (tests/fuzz/parser_fuzzer.cpp) with libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer for a bounded time, and fails on any finding:
# a crash, a sanitizer report, an exception other than InputError, a leak, an input that runs
# longer than 5 s, or more than 2 GB of memory. Usage: scripts/fuzz.sh [seconds] (default 60).
# The corpus grows in build-fuzz/corpus across runs; findings are written to build-fuzz/findings/
# (reproduce one with build-fuzz/tests/fuzz/parser_fuzzer FILE).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
scripts/setup.sh
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCAUSTICA_FUZZ=ON -DCAUSTICA_BUILD_BENCHMARKS=OFF
cmake --build build-fuzz -j2 --target parser_fuzzer

# Seeds: every scene in the repository, the malformed corpus included, and the multi-file
# seeds of tests/fuzz/seeds (files named after their path, so that equal names do not clash).
seeds=build-fuzz/seeds
rm -rf "$seeds"
mkdir -p "$seeds" build-fuzz/corpus build-fuzz/findings
find scenes tests/data tests/fuzz/seeds -name '*.pbrt' -print0 |
  while IFS= read -r -d '' f; do cp "$f" "$seeds/${f//\//_}"; done

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
build-fuzz/tests/fuzz/parser_fuzzer build-fuzz/corpus "$seeds" \
  -dict=tests/fuzz/pbrt.dict -max_len=65536 -max_total_time="$seconds" -timeout=5 \
  -rss_limit_mb=2048 -artifact_prefix=build-fuzz/findings/ -print_final_stats=1
echo "fuzz: no findings in ${seconds} s"
