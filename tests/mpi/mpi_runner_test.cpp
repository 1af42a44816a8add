// run_study_distributed on the 2 ranks of `mpirun -np 2` (this file is an MPI program: every case
// runs on both ranks together, rank 0 the writer): the files run_study writes in one process,
// byte for byte, with the runs really spread; a stop on rank 0 interrupts every rank and the study
// resumes; a rank that stops gives its runs back; a shard; an error on rank 0 ends every rank; a
// rank 0 that never runs the study releases the others. Cases use EXPECT, not ASSERT, once both
// ranks are in the exchange: a rank leaving a case early would leave the other waiting for it.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <gtest/gtest.h>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "results/store/study_writer.hpp"
#include "runner/distribution/mpi/mpi_runner.hpp"
#include "runner/distribution/shards.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;
using test_support::read_text;

const MpiSession* session = nullptr;

bool is_writer() {
    return session->rank() == 0;
}

// Costs a thousandfold apart: random search's evaluations are nearly free, CMA-ES's are not, and
// TLBO's iteration budget spends about twice the evaluations.
PreparedStudy make_study() {
    Study s;
    s.algorithms = {"random-search:batch=50", "tlbo", "cmaes"};
    s.problems = {"sphere:dim=5", "rastrigin:dim=5"};
    s.runs = 4;
    s.seed = 11;
    s.budgets.front().max_evaluations = 20000;
    return prepare_study(s);
}

// Only rank 0 touches the directories; the name carries its process id (CTest may run other
// test programs alongside).
fs::path directory(const std::string& name) {
    return fs::temp_directory_path() / ("mhb_mpi_runner_" + name + "_" + std::to_string(::getpid()));
}

fs::path fresh(const std::string& name) {
    const fs::path dir = directory(name);
    if (is_writer())
        fs::remove_all(dir);
    return dir;
}

RunnerOutcome run_distributed(const PreparedStudy& study, const fs::path& dir, const RunnerOptions& options,
                              DistributedStats* stats = nullptr) {
    std::optional<StudyWriter> writer;
    if (is_writer())
        writer.emplace(dir, study_ini(study.study), "threads = test\n", study.parameter_columns, false);
    return run_study_distributed(study, writer ? &*writer : nullptr, options, *session, stats);
}

// The one-process run, on rank 0 only (rank 1 meanwhile waits in the next distributed call).
fs::path reference(const PreparedStudy& study, const std::string& name, const RunnerOptions& options = {}) {
    const fs::path dir = fresh("reference_" + name);
    if (is_writer()) {
        StudyWriter writer(dir, study_ini(study.study), "threads = test\n", study.parameter_columns, false);
        EXPECT_FALSE(run_study(study, writer, options).interrupted);
    }
    return dir;
}

void expect_same_files(const fs::path& dir, const fs::path& reference_dir) {
    if (!is_writer())
        return;
    for (const char* file : {"runs.csv", "curves.csv", "checkpoints.csv", "trajectories.csv", "study.ini"}) {
        EXPECT_TRUE(fs::exists(dir / file)) << file;
        EXPECT_EQ(read_text(dir / file), read_text(reference_dir / file)) << file;
    }
}

TEST(MpiRunner, TwoRanksWriteTheFilesOneProcessWritesAndShareTheRuns) {
    ASSERT_EQ(session->size(), 2) << "run under mpirun -np 2";
    const PreparedStudy study = make_study();
    const fs::path one = reference(study, "all");
    const fs::path dir = fresh("all");
    RunnerOptions options;
    options.threads = 2;
    std::vector<std::int64_t> progress;
    options.on_run_finished = [&](std::int64_t kept, std::int64_t total, const RunRecord& record) {
        EXPECT_EQ(total, 24);
        EXPECT_GT(record.evaluations, 0);
        progress.push_back(kept);
    };
    DistributedStats stats;
    const RunnerOutcome outcome = run_distributed(study, dir, options, &stats);
    // Every rank returns rank 0's outcome.
    EXPECT_EQ(outcome.total, 24);
    EXPECT_EQ(outcome.resumed, 0);
    EXPECT_EQ(outcome.kept, 24);
    EXPECT_FALSE(outcome.interrupted);
    expect_same_files(dir, one);
    if (is_writer()) {
        // Rank 0 reports every run once, in order, whichever rank ran it; both ranks ran some.
        ASSERT_EQ(progress.size(), 24u);
        for (std::size_t i = 0; i < progress.size(); ++i)
            EXPECT_EQ(progress[i], static_cast<std::int64_t>(i + 1));
        ASSERT_EQ(stats.runs_by_rank.size(), 2u);
        EXPECT_EQ(stats.runs_by_rank[0] + stats.runs_by_rank[1], 24);
        EXPECT_GT(stats.runs_by_rank[0], 0);
        EXPECT_GT(stats.runs_by_rank[1], 0);
    } else {
        EXPECT_TRUE(progress.empty()); // only rank 0 reports
    }

    // The same study again: everything is in the store, nothing runs, the files are the same.
    const RunnerOutcome again = run_distributed(study, dir, options, &stats);
    EXPECT_EQ(again.resumed, 24);
    EXPECT_EQ(again.kept, 24);
    EXPECT_FALSE(again.interrupted);
    if (is_writer()) {
        EXPECT_EQ(stats.runs_by_rank, (std::vector<std::int64_t>{0, 0}));
    }
    expect_same_files(dir, one);
}

TEST(MpiRunner, AStopOnRankZeroInterruptsEveryRankAndTheStudyResumes) {
    const PreparedStudy study = make_study();
    const fs::path one = reference(study, "stopped");
    const fs::path dir = fresh("stopped");
    std::atomic<bool> stop{false};
    RunnerOptions options;
    options.threads = 1;
    options.stop = &stop;
    options.on_run_finished = [&](std::int64_t kept, std::int64_t, const RunRecord&) {
        if (kept >= 3)
            stop = true;
    };
    const RunnerOutcome first = run_distributed(study, dir, options);
    EXPECT_TRUE(first.interrupted);
    EXPECT_GE(first.kept, 3);
    EXPECT_LT(first.kept, 24);
    if (is_writer()) {
        EXPECT_FALSE(fs::exists(dir / "runs.csv"));
    }

    const RunnerOutcome second = run_distributed(study, dir, RunnerOptions{});
    EXPECT_FALSE(second.interrupted);
    EXPECT_EQ(second.resumed, first.kept);
    EXPECT_EQ(second.kept, 24);
    expect_same_files(dir, one);
}

TEST(MpiRunner, ARankThatStopsGivesItsRunsBackAndRankZeroDoesThem) {
    const PreparedStudy study = make_study();
    const fs::path dir = fresh("given_back");
    std::atomic<bool> stop{false};
    RunnerOptions options;
    options.threads = 2;
    options.stop = &stop;
    // Rank 1 stops a little after it starts, holding runs it has not started (it keeps twice its
    // threads); however the timing falls, rank 0 must do whatever rank 1 did not.
    std::optional<std::thread> stopper;
    if (!is_writer())
        stopper.emplace([&stop] {
            std::this_thread::sleep_for(std::chrono::milliseconds(30));
            stop = true;
        });
    DistributedStats stats;
    const RunnerOutcome outcome = run_distributed(study, dir, options, &stats);
    if (stopper)
        stopper->join();
    EXPECT_FALSE(outcome.interrupted);
    EXPECT_EQ(outcome.kept, 24);
    if (is_writer()) {
        EXPECT_GT(stats.runs_by_rank[0], 0);
    }
    // The reference after the exchange, so that both ranks start it together and rank 1's stop
    // falls while it holds runs.
    expect_same_files(dir, reference(study, "given_back"));
}

TEST(MpiRunner, AShardRunsOnlyItsRuns) {
    const PreparedStudy study = make_study();
    RunnerOptions options;
    options.run_ids = shard_run_ids(study, 3)[1];
    const fs::path one = reference(study, "shard", options);
    const fs::path dir = fresh("shard");
    const RunnerOutcome outcome = run_distributed(study, dir, options);
    EXPECT_EQ(outcome.total, static_cast<std::int64_t>(options.run_ids->size()));
    EXPECT_EQ(outcome.kept, outcome.total);
    EXPECT_FALSE(outcome.interrupted);
    expect_same_files(dir, one);
}

TEST(MpiRunner, AnErrorOnRankZeroEndsTheStudyOnEveryRank) {
    const PreparedStudy study = make_study();
    const fs::path dir = fresh("error");
    RunnerOptions options;
    options.on_run_finished = [](std::int64_t kept, std::int64_t, const RunRecord&) {
        if (kept == 2)
            throw std::runtime_error("the progress display failed");
    };
    try {
        (void)run_distributed(study, dir, options);
        ADD_FAILURE() << "no error on rank " << session->rank();
    } catch (const std::runtime_error& e) {
        const std::string expected =
            is_writer() ? "the progress display failed" : "MPI rank 0 stopped the study on an error";
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    if (is_writer()) {
        EXPECT_FALSE(fs::exists(dir / "runs.csv"));
    }
}

TEST(MpiRunner, ARankZeroThatDoesNotRunTheStudyReleasesTheOthers) {
    const PreparedStudy study = make_study();
    if (is_writer()) {
        release_waiting_ranks(*session); // as when rank 0 refuses the study directory
        return;
    }
    try {
        (void)run_study_distributed(study, nullptr, RunnerOptions{}, *session);
        ADD_FAILURE() << "rank 1 ran a study rank 0 never started";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("ended before running the study"), std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace mhb

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    const mhb::MpiSession mpi;
    mhb::session = &mpi;
    return RUN_ALL_TESTS();
}
