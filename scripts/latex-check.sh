#!/usr/bin/env bash
# The LaTeX of real reports through pdflatex: installs TeX Live's latex-base and latex-recommended,
# and texlive-publishers (the IEEEtran and elsarticle classes) with texlive-fonts-recommended (the
# Times fonts of IEEEtran) (set-up group `tex`; CI does not install texlive-science, so siunitx is
# not assumed), builds the release preset's CLI and LaTeX tests, and runs the CTest label latex
# (tests/latex/: report.tex of the paper study and of an ablation with two budgets, every table file
# on its own, the tables of an ablation in \documentclass[conference]{IEEEtran} and
# \documentclass[5p]{elsarticle} (two columns), and the golden fixture tests/data/latex/report.tex
# compile with no error, no Overfull \hbox and no float too large for the page). CI runs it after
# the main test suite. Extra arguments go to ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup-debian.sh tex
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)" --target mhbench test_latex
ctest --preset release -L latex "$@"
