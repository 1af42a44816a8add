// A failed run in the store is no result: a writer reopening the study does not count it as
// completed (so the same command computes it again), says how many it retries, and the retry's
// record replaces the failure in what is rendered.
#include <filesystem>
#include <gtest/gtest.h>

#include "results/store/run_key.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

RunRecord sphere_record(std::int64_t id, bool ok) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = "de";
    r.problem = "sphere:dim=2";
    r.budget = "evaluations=40";
    r.run_index = id;
    r.seed = 7 + static_cast<std::uint64_t>(id);
    r.ok = ok;
    r.evaluations = ok ? 40 : 17; // a failure records what it spent
    r.iterations = ok ? 4 : 1;
    r.best_f = ok ? 0.5 : r.best_f;
    r.best_x = {0.5, 0.5};
    r.message = ok ? "" : "the model's program exited with status 3";
    return r;
}

StudyWriter open_two_runs(const fs::path& dir) {
    StudyRunKeys keys;
    keys.count = 2;
    keys.key = [](std::int64_t id) {
        RunKey key;
        key.identity = "identity " + std::to_string(id);
        key.slot = "de | sphere:dim=2 | " + std::to_string(id);
        key.algorithm = "de";
        key.problem = "sphere:dim=2";
        return key;
    };
    return StudyWriter(dir, "[study]\nruns = 2\n", "", {}, false, {}, std::move(keys));
}

TEST(StoreFailedRuns, AStoredFailureIsRetriedAndItsNewRecordReplacesIt) {
    const fs::path dir = fs::temp_directory_path() / "mhb_store_failed_runs";
    fs::remove_all(dir);
    {
        StudyWriter w = open_two_runs(dir);
        w.append(sphere_record(0, true), 0.1);
        w.append(sphere_record(1, false), 0.1);
        w.finish();
        EXPECT_EQ(w.summary().failed, 1);
    }
    EXPECT_EQ(load_study(dir).runs.at(1).evaluations, 17);
    {
        StudyWriter w = open_two_runs(dir);
        EXPECT_EQ(w.completed(), (std::set<std::int64_t>{0}));
        EXPECT_EQ(w.retried_failures(), 1);
        w.append(sphere_record(1, true), 0.1);
        w.finish();
        EXPECT_EQ(w.summary().failed, 0);
    }
    const StudyData study = load_study(dir);
    ASSERT_EQ(study.runs.size(), 2U);
    EXPECT_TRUE(study.runs[1].ok);
    EXPECT_EQ(study.runs[1].evaluations, 40);
    // The failure's block stays in store.bin, unused: reopening finds nothing to retry.
    const StudyWriter again = open_two_runs(dir);
    EXPECT_EQ(again.completed(), (std::set<std::int64_t>{0, 1}));
    EXPECT_EQ(again.retried_failures(), 0);
    fs::remove_all(dir);
}

} // namespace
} // namespace mhb
