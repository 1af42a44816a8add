#!/usr/bin/env bash
# Quick start 2: set-up, Release build and the whole test suite (unit, integration and slow
# labels) under CTest. Extra arguments go to ctest (e.g. -L unit, -R Pmsm).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/build.sh
ctest --preset release -j"$(nproc)" "$@"
