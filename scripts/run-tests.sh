#!/usr/bin/env bash
# Quick start 2: set-up, Release build and the whole test suite (unit, integration and slow
# labels) under CTest. Extra arguments go to ctest (e.g. -L unit, -R Pmsm).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/build.sh
# MHB_QUICKSTART_CHECK=1 (the README's front-page test, itself part of the suite): one quick test
# shows the command works without running the suite from inside the suite.
if [ "${MHB_QUICKSTART_CHECK:-}" = 1 ]; then
    exec ctest --preset release -R '^IncludeLayering$' "$@"
fi
ctest --preset release -j"$(nproc)" "$@"
