#!/usr/bin/env bash
# The whole test suite, built twice from the top of a clone (README, .ci/run):
#   build/       Release with GCC, the build users run: every test;
#   build-asan/  clang at -O1 -g1 (the sanitized build's compile time is most of the
#                suite's; -O1 keeps ASan's reports exact, -g1 keeps file:line in them)
#                with AddressSanitizer and UndefinedBehaviorSanitizer
#                (-DFRAMEDYN_SANITIZE=address,undefined) and libFuzzer's coverage
#                instrumentation of the readers' libraries (-DFRAMEDYN_FUZZ=ON; not of
#                the tests, whose compile it made up to 8x slower): the fast tier again
#                (-DFRAMEDYN_BUILD_SLOW_TESTS=OFF: the slow tier's whole studies run the
#                code the fast tier reaches, for minutes more under the sanitizers, and
#                CI's 45 minutes do not hold both), where any report (memory error,
#                leak, undefined behaviour) stops the program and fails its test, and
#                the short fuzz runs of the readers, whose harnesses link the same
#                sanitized libraries (one sanitized compile serves both).
# Stops at the first failure. Two cores (-j2), as in CI.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== $(date -u +%T) Release build and tests (build/)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFRAMEDYN_BUILD_TESTS=ON
cmake --build build -j2
ctest --test-dir build --output-on-failure -j2

echo "== $(date -u +%T) Sanitized build and tests: AddressSanitizer + UndefinedBehaviorSanitizer, fuzz runs (build-asan/)"
cmake -S . -B build-asan -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DFRAMEDYN_SANITIZE=address,undefined -DFRAMEDYN_FUZZ=ON -DFRAMEDYN_BUILD_TESTS=ON -DFRAMEDYN_BUILD_SLOW_TESTS=OFF -DFRAMEDYN_PYTHON=OFF  # no Python module: an ASan extension needs the runtime preloaded into python
cmake --build build-asan -j2
ctest --test-dir build-asan --output-on-failure -j2
echo "== $(date -u +%T) suite done"
