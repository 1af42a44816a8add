#!/usr/bin/env bash
# Installs the Debian packages mhbench needs, if any are missing (as root, or through sudo).
# Every dependency comes from Debian: nothing is downloaded at build time.
# Optional groups are named as arguments: `setup-debian.sh fuzz` adds clang and libFuzzer,
# `setup-debian.sh mpi` Open MPI (the MHB_WITH_MPI build, scripts/mpi.sh), `setup-debian.sh tidy`
# clang-tidy and Ninja (scripts/clang-tidy.sh), `setup-debian.sh ccache`
# the compiler cache CI shares between its release and MPI builds, `setup-debian.sh browser` Chromium
# (report/index.html checked in a headless browser: scripts/browser-check.sh), `setup-debian.sh tex`
# pdflatex with latex-base and latex-recommended, and the journal classes IEEEtran and elsarticle
# (texlive-publishers) with the Times fonts IEEEtran uses (texlive-fonts-recommended): report.tex
# and the tables in two-column journals compiled by scripts/latex-check.sh, `setup-debian.sh octave`
# Octave for the external protocol's Octave client (scripts/octave-check.sh), `setup-debian.sh pagmo`
# pagmo2, the yardstick of the whole-process comparison (scripts/pagmo-compare.sh).
set -euo pipefail

packages=(
    build-essential cmake git pkg-config # compiler and build
    libeigen3-dev                        # linear algebra
    libtbb-dev                           # oneTBB: the parallel runner
    libnlopt-cxx-dev                     # NLopt baselines (C++ API)
    libboost-dev                         # Boost.Math: distributions and p-values
    libboost-program-options-dev         # the CLI and study files
    nettle-dev                           # GNU Nettle: SHA-256 of data files and run identities
    libarchive-dev                       # libarchive: the embedded CEC 2017/2022 data (tar, xz)
    nlohmann-json3-dev                   # nlohmann-json: the external protocol's JSON lines
    libgtest-dev libgmock-dev            # GoogleTest
    libbenchmark-dev                     # Google Benchmark
    python3-matplotlib                   # figures (Debian's /usr/bin/python3)
    python3-munkres                      # what matplotlib's font tools need instead of SciPy (200 MB)
    python3-pandas                       # scripts/python/mhbench_study.py: a study as DataFrames
)
optional_fuzz=(clang libclang-rt-dev)    # scripts/fuzz.sh: clang with libFuzzer and its sanitizers
optional_mpi=(libopenmpi-dev openmpi-bin) # scripts/mpi.sh: Open MPI for `mpirun -np N mhbench run`
optional_tidy=(clang-tidy ninja-build)   # scripts/clang-tidy.sh: clang-tidy, and Ninja for the headers it reads
optional_ccache=(ccache)                 # .ci/run: the MPI build reuses the release build's objects
optional_browser=(chromium)              # scripts/browser-check.sh: the HTML report in headless Chromium
optional_tex=(texlive-latex-base texlive-latex-recommended lmodern # scripts/latex-check.sh: pdflatex,
    texlive-publishers texlive-fonts-recommended)                    # IEEEtran, elsarticle, Times
optional_octave=(octave)                 # scripts/octave-check.sh: the external protocol's Octave client
optional_pagmo=(libpagmo-dev)            # scripts/pagmo-compare.sh: pagmo2's PSO, timed beside mhbench's

for group in "$@"; do
    case "$group" in
    fuzz) packages+=("${optional_fuzz[@]}") ;;
    mpi) packages+=("${optional_mpi[@]}") ;;
    tidy) packages+=("${optional_tidy[@]}") ;;
    ccache) packages+=("${optional_ccache[@]}") ;;
    browser) packages+=("${optional_browser[@]}") ;;
    tex) packages+=("${optional_tex[@]}") ;;
    octave) packages+=("${optional_octave[@]}") ;;
    pagmo) packages+=("${optional_pagmo[@]}") ;;
    *)
        echo "mhbench set-up: unknown optional group '$group' (known: fuzz, mpi, tidy, ccache, browser, tex, octave, pagmo)" >&2
        exit 2
        ;;
    esac
done

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "mhbench set-up: installing ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
    sudo=()
elif command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
else
    echo "mhbench set-up: these packages are missing and neither root nor sudo is available: ${missing[*]}" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
