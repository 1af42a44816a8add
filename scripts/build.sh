#!/usr/bin/env bash
# Set-up and Release build shared by the README's two commands: installs missing Debian
# packages, configures with the `release` preset and builds with every core.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup-debian.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
