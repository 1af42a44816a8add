// Where a study's runs execute: in this process alone, or over every rank of an MPI job when
// mhbench is built with MHB_WITH_MPI and started by `mpirun -np N` (N > 1). `mhbench run` calls
// these instead of run_study, so one code path serves both; without MPI they cost nothing.
//
// Under MPI, rank 0 is the only one that touches the study directory: it creates the
// StudyWriter, prints, and builds the report. The other ranks prepare the same study from the
// same command line and execute the runs rank 0 hands out (runner/distribution/mpi/mpi_runner.hpp).
#pragma once

#include <string>
#include <vector>

#include "runner/execution/parallel_runner.hpp"
#include "runner/study/study.hpp"

namespace mhb {

class StudyWriter; // results/store/study_writer.hpp

// The process count a launcher (mpirun, mpiexec, srun -n N: runner/distribution/launcher_environment.hpp)
// gave this process in its environment, or 0 when none started it.
int launcher_process_count();
inline bool launched_under_mpi() {
    return launcher_process_count() > 0;
}

// Whether this mhbench was built with MHB_WITH_MPI.
bool built_with_mpi();

// This process's rank, 0 outside MPI. The first call under a launcher initialises MPI (it is
// ended when the process exits), so a plain `mhbench run` never starts it. Throws
// std::runtime_error when a launcher started several processes of an mhbench built without
// MPI: each would run the whole study into the one directory.
int distributed_rank();
// The number of ranks the runs are spread over: 1 outside MPI.
int distributed_rank_count();
// Under MPI (N > 1 ranks), collective: the lines naming each data file that a rank read with
// another content than rank 0 (runner/distribution/mpi/rank_data_check.hpp), to be refused before any run;
// none when all agree, and outside MPI.
std::vector<std::string> distributed_data_differences(const PreparedStudy& study);
// "mpi_ranks = N\n" for context.ini when the runs are spread over N > 1 ranks, else "".
std::string distributed_context();

// Collective under MPI (N > 1 ranks): rank 0's `more` on every rank, which says whether another
// round of runs by precision follows (runner/execution/precision_rounds.hpp); `more` elsewhere.
bool distributed_another_round(bool more);

// run_study's contract, on every rank: `writer` is non-null exactly on rank 0 (the one writer),
// which alone reads options.run_ids and calls options.on_run_finished (for the runs of every
// rank). options.threads is each rank's own. options.stop stops the rank it is set on: rank 0
// hands out no more runs (the study is interrupted once the runs under way are stored),
// another rank gives back the runs it has not started. Every rank returns the same outcome.
// Outside MPI (or with one rank) this is run_study(study, *writer, options).
RunnerOutcome run_study_anywhere(const PreparedStudy& study, StudyWriter* writer,
                                 const RunnerOptions& options);

} // namespace mhb
