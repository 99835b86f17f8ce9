#!/usr/bin/env bash
# Builds and runs the whole test suite: the Release build with every test (unit, command
# line, examples, the cross-check against the Python reference) under ctest. With CI set
# (as in .ci/run), warnings are errors.
#
# --sanitize first builds the unit tests in a Debug build with AddressSanitizer and
# UndefinedBehaviorSanitizer and runs them (about 10 minutes on 2 cores: the exhaustive
# lemma checks are slow without optimisation), then does the above.
set -euo pipefail
cd "$(dirname "$0")/.."
werror=OFF
[ -n "${CI:-}" ] && werror=ON

if [ "${1:-}" = "--sanitize" ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DTIOA_SANITIZE=ON -DTIOA_WERROR=$werror
  cmake --build build-asan --target unit_tests
  for tests in support tioa checker models proofs catalogue; do
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 build-asan/tests/${tests}_tests
  done
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTIOA_WERROR=$werror
cmake --build build
ctest --test-dir build --output-on-failure -j"$(nproc 2>/dev/null || echo 2)"
