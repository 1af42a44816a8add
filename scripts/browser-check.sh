#!/usr/bin/env bash
# The HTML report (report/index.html) in a real browser: installs Debian's Chromium (set-up group
# `browser`), builds the release preset and runs the CTest label browser (tests/browser/: real
# studies' pages hold every table and figure with JavaScript on and off, sort by a click, and make
# no network request). CI runs it after the main test suite. Extra arguments go to ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup-debian.sh browser
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
ctest --preset release -L browser "$@"
