#include "runner/distribution/distributed.hpp"

#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "runner/distribution/launcher_environment.hpp"

#if MHB_WITH_MPI
#include "runner/distribution/mpi/mpi_runner.hpp"
#include "runner/distribution/mpi/rank_data_check.hpp"
#endif

namespace mhb {
namespace {

#if MHB_WITH_MPI
// The MPI session of this process: started on first use under a launcher, ended at exit.
struct Distributed {
    MpiSession session;
    bool ran = false;
    Distributed() = default;
    Distributed(const Distributed&) = delete;
    Distributed& operator=(const Distributed&) = delete;
    // Rank 0 may end without running the study (it refused the directory, say): the other ranks
    // are waiting for runs then, and must be told before MPI is finalised, or all would hang.
    ~Distributed() {
        if (!ran)
            release_waiting_ranks(session);
    }
};

Distributed* distributed() {
    static const std::unique_ptr<Distributed> instance =
        launched_under_mpi() ? std::make_unique<Distributed>() : nullptr;
    return instance.get();
}
#endif

} // namespace

int launcher_process_count() {
    return launched_processes(std::getenv).count;
}

bool built_with_mpi() {
#if MHB_WITH_MPI
    return true;
#else
    return false;
#endif
}

int distributed_rank() {
#if MHB_WITH_MPI
    const Distributed* d = distributed();
    return d != nullptr ? d->session.rank() : 0;
#else
    if (const LaunchedProcesses launched = launched_processes(std::getenv); launched.count > 1)
        throw std::runtime_error("this mhbench was built without MPI, yet a launcher started it as one of " +
                                 std::string(launched.at_least ? "at least " : "") +
                                 std::to_string(launched.count) + " processes (" + launched.evidence +
                                 "), which would each run the whole study: run one process (no mpirun, "
                                 "no srun -n N), or build it with -DMHB_WITH_MPI=ON (the mpi preset)");
    return 0;
#endif
}

int distributed_rank_count() {
#if MHB_WITH_MPI
    const Distributed* d = distributed();
    return d != nullptr ? d->session.size() : 1;
#else
    return 1;
#endif
}

std::vector<std::string> distributed_data_differences(const PreparedStudy& study) {
#if MHB_WITH_MPI
    if (Distributed* d = distributed(); d != nullptr && d->session.size() > 1) {
        std::vector<std::string> differences = rank_data_differences(study, d->session);
        // Every rank ends without a run: none will wait for rank 0 to release it.
        d->ran = d->ran || !differences.empty();
        return differences;
    }
#endif
    (void)study;
    return {};
}

bool distributed_another_round(bool more) {
#if MHB_WITH_MPI
    if (Distributed* d = distributed(); d != nullptr && d->session.size() > 1)
        return d->session.broadcast(more);
#endif
    return more;
}

std::string distributed_context() {
    const int ranks = distributed_rank_count();
    return ranks > 1 ? "mpi_ranks = " + std::to_string(ranks) + "\n" : "";
}

RunnerOutcome run_study_anywhere(const PreparedStudy& study, StudyWriter* writer,
                                 const RunnerOptions& options) {
#if MHB_WITH_MPI
    if (Distributed* d = distributed(); d != nullptr && d->session.size() > 1) {
        d->ran = true;
        return run_study_distributed(study, writer, options, d->session);
    }
#endif
    if (writer == nullptr)
        throw std::logic_error("run_study_anywhere: no StudyWriter outside an MPI job of several ranks");
    return run_study(study, *writer, options);
}

} // namespace mhb
