#!/usr/bin/env bash
# clang-tidy over the repository's own C++ sources with .clang-tidy's checks (bugprone-*,
# performance-*, less those it names): any warning fails. Installs clang-tidy (and clang, Open MPI
# and Ninja: the build it reads) if missing.
#   scripts/clang-tidy.sh [REGEX]   only the batches whose path matches (e.g. mhb_runner, test_unit_results)
#
# It reads build/tidy/compile_commands.json, a configuration of its own (configured, never built):
# clang, so that clang-tidy reads the flags it was given; MPI and the fuzz targets on, so that
# every source of the repository is a compile command (but tests/bench/pagmo, an optional build,
# and the CEC organisers' reference driver in tests/data); Debug, so that assert() is seen. The
# sources are read in the unity batches the build compiles (cmake/MhbUnityBuild.cmake): clang-tidy
# spends most of its time matching its checks against the standard library, Eigen and Boost, once
# per translation unit, and a batch reads them once for sixteen sources. Warnings in the batched
# sources are reported as in any header of the repository (the -header-filter below).
#
# Time: 63 translation units, 8 min 20 s to 9 min of CPU (user): 4 min 48 s wall on the project's
# 2-vCPU VM with other builds running (load 3 to 4), about 4.5 minutes on 2 idle cores. With the
# whole of bugprone-* and performance-* it was 11 min 20 s of CPU; with clang-analyzer-* as well
# (the default set that `-*` now removes) 12 min 20 s. One source at a time would be 340 translation
# units, not 63, each parsing the standard library, Eigen and Boost anew.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup-debian.sh tidy fuzz mpi
build="$root/build/tidy"
cmake -G Ninja -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ \
    -DMHB_WITH_MPI=ON -DMHB_FUZZ=ON -DMHB_UNITY_BUILD=ON -DMHB_PRECOMPILE_HEADERS=OFF >/dev/null
# The plug-in contract's fingerprint headers (cmake/mhbenchPlugin.cmake) are the only generated
# headers the sources include: each is written by its final command alone, without building the
# libraries Ninja would build first.
grep -o -- '-include [^ ]*_contract/mhbench_contract\.hpp' "$build/compile_commands.json" | cut -d' ' -f2 |
    sort -u | while read -r header; do
    (cd "$build" && ninja -t commands -s "$header" | sh)
done
# The batch files include the sources by absolute path; a batch's warnings are those of its sources
# (a header of the repository's, not one of build/: the generated preset file is CMake's text).
# bugprone-suspicious-include is left out here only: a batch includes .cpp files by design (no
# source of the repository does; each is checked by the compiler's own build as it stands).
run-clang-tidy -quiet -j "$(nproc)" -p "$build" \
    -header-filter="^$root/(algorithms|problems|results|runner|scripts|tests)/" \
    -checks=-bugprone-suspicious-include "${1:-.}" 2>&1 |
    { grep -v -e '^[0-9]* warnings\( and [0-9]* errors\)\? generated\.$' -e '^Suppressed [0-9]* warnings' \
        -e '^Use -header-filter=' -e '^Use -system-headers' || true; }
