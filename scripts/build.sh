#!/usr/bin/env bash
# Set-up and Release build shared by the README's two commands: installs missing Debian
# packages, configures with the `release` preset and builds with every core.
#   scripts/build.sh            every target (the library, the CLI, the tests and benchmarks)
#   scripts/build.sh mhbench    only the named targets (the paper's study needs the CLI alone)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup-debian.sh
cmake --preset release >/dev/null
targets=()
[ $# -gt 0 ] && targets=(--target "$@")
cmake --build --preset release -j"$(nproc)" "${targets[@]}"
