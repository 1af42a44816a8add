#!/usr/bin/env bash
# Set-up and Release build shared by the README's two commands: installs missing Debian
# packages, configures with the `release` preset and builds with every core.
#   scripts/build.sh            every target (the library, the CLI, the tests and benchmarks)
#   scripts/build.sh mhbench    only the named targets (the paper's study needs the CLI alone)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
# MHB_QUICKSTART_CHECK=1: the README's front-page test (tests/readme/front_page_test.py) runs the
# quick start inside a CTest run whose build is already done: nothing to install or build.
if [ "${MHB_QUICKSTART_CHECK:-}" = 1 ]; then
    [ -x build/release/runner/mhbench ] || { echo "build.sh: no build/release/runner/mhbench to check" >&2; exit 1; }
    echo "build.sh: MHB_QUICKSTART_CHECK=1, set-up and build skipped" >&2
    exit 0
fi
bash scripts/setup-debian.sh
cmake --preset release >/dev/null
targets=()
[ $# -gt 0 ] && targets=(--target "$@")
cmake --build --preset release -j"$(nproc)" "${targets[@]}"
