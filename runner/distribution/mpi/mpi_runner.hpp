// `mpirun -np N mhbench run`: a study's runs spread over the ranks of an MPI job. Run costs
// differ by orders of magnitude between optimisers, so runs are handed out on demand, never split
// in advance: rank 0 keeps the runs to do, most expensive first (the shards' cost estimate,
// runner/distribution/shards.hpp), so that long runs start early and the short ones fill the gaps at the end.
// Every rank, rank 0 included, executes runs on a oneTBB arena of its own threads and asks rank
// 0 for more while it holds no more than its thread count (it keeps up to twice that, so a thread
// never waits for an answer). Rank 0 is the one writer: it journals each record the moment it
// arrives, so a rank that dies loses only the runs it held, and the same command resumes.
// Records are byte-identical to a one-process run: a run's record depends on its run id alone,
// records travel exactly (results/store/record_codec.hpp), and the writer sorts by run id.
//
// Only the thread that created the MpiSession calls MPI. Each rank's communication loop polls
// (MPI_Iprobe, MPI_Test) and sleeps between polls, from 50 us up to 1 ms when nothing happens:
// Open MPI's blocking calls spin, and a spinning rank 0 would take a core from its own workers.
#pragma once

#include <cstdint>
#include <vector>

#include "runner/distribution/mpi/mpi_session.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/study/study.hpp"

namespace mhb {

class StudyWriter; // results/store/study_writer.hpp

// How the work was spread, filled on rank 0 (tests, benchmarks).
struct DistributedStats {
    std::vector<std::int64_t> runs_by_rank; // the runs each rank executed in this call
};

// run_study's contract, on every rank of `session` (see runner/distribution/distributed.hpp): `writer` is
// non-null exactly on rank 0. Every rank returns the outcome rank 0 computed. When rank 0 fails
// (a write error, say) the others drain their runs and throw std::runtime_error too; a rank that
// cannot go on with the exchange (a malformed message) ends the job with MPI_Abort, since the
// others would otherwise wait for it forever.
RunnerOutcome run_study_distributed(const PreparedStudy& study, StudyWriter* writer,
                                    const RunnerOptions& options, const MpiSession& session,
                                    DistributedStats* stats = nullptr);

// For rank 0 when it ends without calling run_study_distributed (it refused the study
// directory, say): answers each other rank's first request so that they throw
// std::runtime_error instead of waiting. Does nothing on other ranks or with one rank.
void release_waiting_ranks(const MpiSession& session);

} // namespace mhb
