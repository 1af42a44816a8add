#!/usr/bin/env bash
# The Octave reference client of the external protocol (scripts/external/sphere_problem.m) against
# a real Octave: installs Debian's octave (set-up group `octave`: about a hundred packages, which is
# why CI does not run this), builds the problems' unit tests and runs the test that drives the
# client (ExternalProblem.TheOctaveClientServesAProblem, skipped by the main suite where octave is
# absent). Extra arguments go to ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup-debian.sh octave
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)" --target test_unit_problems
ctest --preset release -R 'ExternalProblem.TheOctaveClientServesAProblem' --no-tests=error "$@"
