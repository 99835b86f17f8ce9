#!/usr/bin/env bash
# Builds and runs the whole test suite: the Release build with every test (unit, command
# line, examples, the cross-check against the Python reference), then the same tests in
# a Debug build with AddressSanitizer and UndefinedBehaviorSanitizer.
# With CI set (as in .ci/run), warnings are errors. --no-sanitize skips the second build.
set -euo pipefail
cd "$(dirname "$0")/.."
werror=OFF
[ -n "${CI:-}" ] && werror=ON
jobs=$(nproc 2>/dev/null || echo 2)

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTIOA_WERROR=$werror
cmake --build build
ctest --test-dir build --output-on-failure -j"$jobs"

if [ "${1:-}" != "--no-sanitize" ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DTIOA_SANITIZE=ON -DTIOA_WERROR=$werror
  cmake --build build-asan
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-asan --output-on-failure -j"$jobs"
fi
