#!/usr/bin/env bash
# Quick start 1: the paper's study end to end — ITLBO vs TLBO vs PSO identifying the PMSM at
# 2500 rpm / 2 N m (NP = 50, 150 iterations, 20 seeds). Prints the verdict, then Tables 2 and 3
# beside the paper's numbers, and writes the study directory (tables, curve data, figures) to studies/paper/.
# Extra arguments go to `mhbench run` (e.g. --threads 1, --out DIR).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
# The CLI alone: the tests are built by the other quick-start command (scripts/run-tests.sh).
bash scripts/build.sh mhbench >&2
build/release/runner/mhbench run --study paper --out studies/paper --overwrite "$@"
# The console shows the verdict; the paper's two tables beside the published numbers follow, from
# the report just written (not when the arguments sent the study elsewhere or asked for quiet).
case " $* " in *" --out"* | *" -q "* | *" --quiet "*) exit 0 ;; esac
for table in table2_fitness table3_parameters; do
    echo
    cat "studies/paper/report/$table.md"
done
