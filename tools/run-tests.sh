#!/usr/bin/env bash
# Builds and runs the whole test suite (what CI runs, .ci/run):
#
# 1. the Release build in build/ with every test under ctest but the opt-in label long: unit,
#    command line, examples, the cross-check against the Python reference;
# 2. the unit tests again, built with AddressSanitizer and UndefinedBehaviorSanitizer in
#    build-asan/ (-O1, assertions on), each test binary run whole except the cases tagged
#    [slow]: exhaustive checks that take over ten seconds there, and that step 1 runs.
#
# Both are unity builds (CMAKE_UNITY_BUILD: a few sources compiled as one), which makes a
# clean build about 2.5 times faster on two cores; configure without it for development,
# where one edited file should recompile alone. With CI set, warnings are errors.
#
#   tools/run-tests.sh                  steps 1 and 2
#   tools/run-tests.sh --no-sanitize    step 1 only
set -euo pipefail
cd "$(dirname "$0")/.."
werror=OFF
[ -n "${CI:-}" ] && werror=ON
sanitize=1
case "${1:-}" in
  "") ;;
  --no-sanitize) sanitize=0 ;;
  *) echo "usage: tools/run-tests.sh [--no-sanitize]" >&2; exit 2 ;;
esac

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON \
  -DTIOA_WERROR=$werror
cmake --build build
# -LE long: the opt-in unit tests tagged [long] (tests/CMakeLists.txt) are left out.
ctest --test-dir build --output-on-failure -LE long -j"$(nproc 2>/dev/null || echo 2)"

if [ $sanitize = 1 ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" \
    -DCMAKE_UNITY_BUILD=ON -DTIOA_SANITIZE=ON -DTIOA_WERROR=$werror
  cmake --build build-asan --target unit_tests
  # The binaries run side by side, one per core (the slowest first); each one's output is
  # kept in build-asan/<name>.log and printed whole when it fails.
  echo "== the unit tests under AddressSanitizer + UndefinedBehaviorSanitizer (not [slow])"
  printf '%s\n' catalogue proofs checker models tioa support |
    xargs -P "$(nproc 2>/dev/null || echo 2)" -I{} sh -c '
      log=build-asan/{}_tests.log
      if ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
           build-asan/tests/{}_tests "~[slow]" > "$log" 2>&1; then
        echo "{}_tests: $(tail -n 2 "$log" | head -n 1)"
      else
        cat "$log"; echo "{}_tests FAILED under the sanitizers"; exit 1
      fi'
fi
