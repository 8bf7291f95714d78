#!/usr/bin/env bash
# Builds the unit and parser tests with AddressSanitizer and UndefinedBehaviorSanitizer and runs
# them (CI's second stage). Any sanitizer report fails the run: UBSan is built not to recover.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
targets=(test_spectral test_params test_parser test_materials test_geometry test_lights test_imaging
         test_scene_generators)
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAUSTICA_SANITIZE=ON \
      -DCAUSTICA_BUILD_BENCHMARKS=OFF
cmake --build build-sanitize -j2 --target "${targets[@]}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
labels=$(printf '%s|' "${targets[@]#test_}")
ctest --test-dir build-sanitize --output-on-failure -j2 -L "^(${labels%|})$"
