// runner/distribution/launcher_environment.hpp with fake environments: every launcher that starts several
// processes is recognised (so a build without MPI can refuse it), and the single-process jobs
// of a scheduler (a batch script, a job-array task, srun -n 1) are not taken for one.
#include <gtest/gtest.h>
#include <map>
#include <string>

#include "runner/distribution/launcher_environment.hpp"

namespace mhb {
namespace {

using Environment = std::map<std::string, std::string>;

LaunchedProcesses launched(const Environment& environment) {
    return launched_processes([&](const char* name) -> const char* {
        const auto found = environment.find(name);
        return found == environment.end() ? nullptr : found->second.c_str();
    });
}

TEST(LauncherEnvironment, EveryLauncherOfSeveralProcessesIsRecognised) {
    struct Case {
        const char* launcher;
        Environment environment;
        int count;
        const char* evidence;
    };
    const Case cases[] = {
        {"mpirun -np 4 (Open MPI)",
         {{"OMPI_COMM_WORLD_SIZE", "4"}, {"OMPI_COMM_WORLD_RANK", "0"}},
         4,
         "OMPI_COMM_WORLD_SIZE=4"},
        {"mpiexec -n 3 (MPICH Hydra, PMI)", {{"PMI_SIZE", "3"}, {"PMI_RANK", "0"}}, 3, "PMI_SIZE=3"},
        {"srun -n 4",
         {{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "4"}, {"SLURM_STEP_NUM_TASKS", "4"}},
         4,
         "SLURM_STEP_NUM_TASKS=4"},
        {"srun -n 4, task 2", {{"SLURM_PROCID", "2"}, {"SLURM_NTASKS", "4"}}, 3, "SLURM_PROCID=2"},
        {"srun --mpi=pmix -n 2, rank 1", {{"PMIX_RANK", "1"}}, 2, "PMIX_RANK=1"},
        {"PMI rank 5, no size", {{"PMI_RANK", "5"}}, 6, "PMI_RANK=5"},
        {"Open MPI rank 1, no size", {{"OMPI_COMM_WORLD_RANK", "1"}}, 2, "OMPI_COMM_WORLD_RANK=1"},
    };
    for (const Case& c : cases) {
        const LaunchedProcesses found = launched(c.environment);
        EXPECT_EQ(found.count, c.count) << c.launcher;
        EXPECT_EQ(found.evidence, c.evidence) << c.launcher;
        EXPECT_EQ(found.at_least, std::string(c.evidence).find("_SIZE") == std::string::npos &&
                                      std::string(c.evidence).find("NUM_TASKS") == std::string::npos)
            << c.launcher;
    }
}

TEST(LauncherEnvironment, TheLargestCountIsTaken) {
    EXPECT_EQ(launched({{"PMI_SIZE", "3"}, {"OMPI_COMM_WORLD_SIZE", "4"}}).count, 4);
    EXPECT_EQ(launched({{"PMI_SIZE", "3"}}).count, 3);
    // mpirun -np 1 in each task of srun -n 4: four processes all the same
    const LaunchedProcesses nested = launched({{"OMPI_COMM_WORLD_SIZE", "1"}, {"SLURM_STEP_NUM_TASKS", "4"}});
    EXPECT_EQ(nested.count, 4);
    EXPECT_EQ(nested.evidence, "SLURM_STEP_NUM_TASKS=4");
    EXPECT_EQ(launched({{"OMPI_COMM_WORLD_SIZE", "4"}, {"OMPI_COMM_WORLD_RANK", "3"}}).evidence,
              "OMPI_COMM_WORLD_SIZE=4"); // a rank inside the size adds nothing
}

TEST(LauncherEnvironment, OneProcessJobsAreNotSeveral) {
    const Environment single[] = {
        {},
        {{"OMPI_COMM_WORLD_SIZE", "1"}, {"OMPI_COMM_WORLD_RANK", "0"}}, // mpirun -np 1
        {{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "1"}, {"SLURM_JOB_ID", "7"}},
        {{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "4"}}, // the batch script of sbatch -n 4: it runs once
        {{"SLURM_PROCID", "0"}, {"SLURM_STEP_NUM_TASKS", "1"}, {"SLURM_NTASKS", "1"}}, // srun -n 1
        {{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_COUNT", "16"}, {"SLURM_PROCID", "0"}},
        {{"PMIX_RANK", "0"}},
    };
    for (const Environment& environment : single)
        EXPECT_LE(launched(environment).count, 1) << environment.size() << " variables";
    EXPECT_EQ(launched({}).count, 0);
    EXPECT_EQ(launched({{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "4"}}).count, 0); // no launch at all
}

TEST(LauncherEnvironment, MalformedValuesSayNothing) {
    for (const char* junk : {"", "two", "2x", "-1", "0", "99999999999999999999"}) {
        EXPECT_EQ(launched({{"OMPI_COMM_WORLD_SIZE", junk}}).count, 0) << junk;
        EXPECT_EQ(launched({{"SLURM_PROCID", junk}}).count, 0) << junk;
    }
}

} // namespace
} // namespace mhb
