// How many processes a launcher started, read from the variables it sets: Open MPI's mpirun
// (OMPI_COMM_WORLD_*), MPICH's Hydra, Intel MPI and PMI-1/2 (PMI_SIZE, PMI_RANK), PMIx launchers
// (PMIX_RANK) and Slurm's srun (SLURM_STEP_NUM_TASKS, SLURM_PROCID). An mhbench built without MPI
// uses it to refuse being started as several processes, each of which would run the whole study.
#pragma once

#include <functional>
#include <string>

namespace mhb {

// getenv, or a fake one in tests.
using EnvironmentLookup = std::function<const char*(const char*)>;

struct LaunchedProcesses {
    int count = 0;         // 0: no launcher started this process
    bool at_least = false; // only a rank says so: there are `count` processes or more
    std::string evidence;  // the variable that says so, "NAME=value"
};

// The largest count any variable shows: a size gives it, a rank r > 0 proves at least r + 1
// (launchers nest: `mpirun -np 1` in each task of `srun -n 4` still makes four). Slurm
// starts every batch job, MPI or not, so its variables count only when they show several tasks
// of one step: SLURM_NTASKS alone is not read, since a batch script of `sbatch -n 4` holds it (and
// SLURM_PROCID = 0) while running once; srun sets SLURM_STEP_NUM_TASKS for the tasks it starts.
// A job-array task (SLURM_ARRAY_TASK_ID, one task each) is one process.
LaunchedProcesses launched_processes(const EnvironmentLookup& lookup);

} // namespace mhb
