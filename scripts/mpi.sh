#!/usr/bin/env bash
# The MPI build (the `mpi` preset: MHB_WITH_MPI=ON with Debian's Open MPI) and its tests (CTest
# label mpi), each of which runs on 2 ranks with `mpirun -np 2 --allow-run-as-root --oversubscribe`,
# so it works as root in CI and on a machine with fewer cores than ranks. Only what those tests
# need is built (mhbench and the two MPI test programs). Extra arguments go to ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup-debian.sh mpi
cmake --preset mpi >/dev/null
cmake --build --preset mpi -j"$(nproc)"
# Open MPI refuses to start as root unless told so, also through these (for any mpirun a test
# adds without the flags). Containers often forbid the cross-process memory reads of its
# shared-memory transport; the copy-in/copy-out path works everywhere and the runner's messages
# are small.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none
ctest --preset mpi "$@"
