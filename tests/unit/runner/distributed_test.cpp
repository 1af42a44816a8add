// runner/distribution/distributed.hpp outside MPI: a plain process is rank 0 of 1 and runs the study itself;
// an MPI launcher is recognised by its environment, and an mhbench built without MPI refuses to
// be started as several processes (each would write the whole study into one directory).
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <optional>
#include <stdexcept>
#include <string>

#include "results/store/study_writer.hpp"
#include "runner/distribution/distributed.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {

// Sets an environment variable for the scope and restores what was there.
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name))
            old_ = old;
        if (value != nullptr)
            ::setenv(name, value, 1);
        else
            ::unsetenv(name);
    }
    ~ScopedEnvironment() {
        if (old_)
            ::setenv(name_, old_->c_str(), 1);
        else
            ::unsetenv(name_);
    }
    ScopedEnvironment(const ScopedEnvironment&) = delete;
    ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

TEST(Distributed, ALauncherIsRecognisedByItsEnvironment) {
    const ScopedEnvironment open_mpi("OMPI_COMM_WORLD_SIZE", nullptr);
    const ScopedEnvironment pmi("PMI_SIZE", nullptr);
    EXPECT_EQ(launcher_process_count(), 0);
    EXPECT_FALSE(launched_under_mpi());
    {
        const ScopedEnvironment slurm("PMI_SIZE", "3");
        EXPECT_EQ(launcher_process_count(), 3);
        const ScopedEnvironment mpirun("OMPI_COMM_WORLD_SIZE", "4"); // Open MPI's own first
        EXPECT_EQ(launcher_process_count(), 4);
        EXPECT_TRUE(launched_under_mpi());
    }
    for (const char* junk : {"", "two", "2x", "-1", "0"}) {
        const ScopedEnvironment bad("OMPI_COMM_WORLD_SIZE", junk);
        EXPECT_EQ(launcher_process_count(), 0) << junk;
    }
}

TEST(Distributed, APlainProcessIsRankZeroOfOneAndRunsTheStudyItself) {
    const ScopedEnvironment open_mpi("OMPI_COMM_WORLD_SIZE", nullptr);
    const ScopedEnvironment pmi("PMI_SIZE", nullptr);
    EXPECT_EQ(distributed_rank(), 0);
    EXPECT_EQ(distributed_rank_count(), 1);
    EXPECT_EQ(distributed_context(), "");

    Study s;
    s.algorithms = {"random-search:batch=5"};
    s.problems = {"sphere:dim=2"};
    s.runs = 3;
    s.budgets.front().max_evaluations = 50;
    const PreparedStudy study = prepare_study(s);
    const auto dir = test_support::fresh_temporary_path("mhb_distributed_", "plain");
    StudyWriter writer(dir, study_ini(study.study), "threads = test\n", study.parameter_columns, false);
    const RunnerOutcome outcome = run_study_anywhere(study, &writer, RunnerOptions{});
    EXPECT_EQ(outcome.total, 3);
    EXPECT_EQ(outcome.kept, 3);
    EXPECT_FALSE(outcome.interrupted);
    EXPECT_TRUE(std::filesystem::exists(dir / "runs.csv"));
    // Only the ranks rank 0 hands runs to go without a writer.
    EXPECT_THROW((void)run_study_anywhere(study, nullptr, RunnerOptions{}), std::logic_error);
}

TEST(Distributed, WithoutMpiSeveralLaunchedProcessesAreRefused) {
    if (built_with_mpi())
        GTEST_SKIP() << "built with MPI: mpirun's processes are ranks (tests/mpi/)";
    const ScopedEnvironment mpirun("OMPI_COMM_WORLD_SIZE", "2");
    try {
        (void)distributed_rank();
        ADD_FAILURE() << "no refusal";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("built without MPI"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("-DMHB_WITH_MPI=ON"), std::string::npos) << e.what();
    }
    const ScopedEnvironment alone("OMPI_COMM_WORLD_SIZE", "1"); // `mpirun -np 1` is one process
    EXPECT_EQ(distributed_rank(), 0);
    {
        // `srun -n 4` sets no MPI variable without an MPI plugin: Slurm's own say it.
        const ScopedEnvironment tasks("SLURM_STEP_NUM_TASKS", "4");
        try {
            (void)distributed_rank();
            ADD_FAILURE() << "srun -n 4 not refused";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("one of 4 processes (SLURM_STEP_NUM_TASKS=4)"),
                      std::string::npos)
                << e.what();
            EXPECT_NE(std::string(e.what()).find("run one process"), std::string::npos) << e.what();
        }
    }
    const ScopedEnvironment batch_script("SLURM_NTASKS", "4"); // `sbatch -n 4`'s script runs once
    const ScopedEnvironment first_task("SLURM_PROCID", "0");
    EXPECT_EQ(distributed_rank(), 0);
}

} // namespace
} // namespace mhb
