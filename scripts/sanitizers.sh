#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer: set-up, build, and every
# CTest label. Any sanitizer report fails the test that triggered it (halt_on_error, and UBSan made
# fatal), so a clean run means no report at all.
#   scripts/sanitizers.sh [ctest args]          GCC, the `asan` preset (build/asan)
#   scripts/sanitizers.sh --clang [ctest args]  clang, the `fuzz` preset (build/fuzz): the same
#       sanitizers plus libFuzzer's coverage, so that scripts/fuzz.sh then reuses the build. CI runs
#       this one: one sanitizer build instead of two.
# Extra arguments go to ctest (e.g. -L unit).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
if [ "${1:-}" = "--clang" ]; then
    shift
    bash scripts/setup-debian.sh fuzz
    configure=fuzz build=fuzz-all tests=fuzz
else
    bash scripts/setup-debian.sh
    configure=asan build=asan tests=asan
fi
cmake --preset "$configure" >/dev/null
cmake --build --preset "$build" -j"$(nproc)"
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=0:strict_string_checks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
ctest --preset "$tests" -j"$(nproc)" "$@"
