// Runs by precision in rounds (runner/execution/precision_rounds.hpp): the same runs and stopping
// points at 1 and 2 threads and after an interruption, each cell stopped where the rule (recomputed
// by the report from the files alone) says, and the rule's study.ini read back as written.
#include <atomic>
#include <filesystem>
#include <gtest/gtest.h>

#include "results/analysis/run_precision.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_index.hpp"
#include "results/store/study_writer.hpp"
#include "runner/execution/precision_rounds.hpp"
#include "runner/execution/run_identity.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "support/files.hpp"

namespace mhb {
namespace precision_rounds_test {
namespace fs = std::filesystem;
using mhb::test_support::read_text;

// Three optimisers that differ by orders of magnitude on two problems: some cells settle at once,
// others need rounds or reach the most.
PreparedStudy make_study() {
    Study s;
    s.algorithms = {"itlbo", "random-search", "tlbo"};
    s.problems = {"sphere:dim=3", "rastrigin:dim=3"};
    s.seed = 3;
    s.budgets.front().max_iterations = 15;
    PrecisionRule rule;
    rule.precision = 0.25;
    rule.initial = 4;
    rule.step = 3;
    rule.max = 16;
    s.by_precision = rule;
    s.runs = rule.max;
    return prepare_study(s);
}

struct Ran {
    RunnerOutcome outcome;
    int rounds = 0;
};

Ran run_into(const fs::path& dir, const PreparedStudy& study, int threads,
             const std::atomic<bool>* stop = nullptr,
             std::function<void(std::int64_t, std::int64_t, const RunRecord&)> on_run = {}) {
    StudyWriter writer(dir, study_ini(study.study), "threads = test\n", study.parameter_columns, false,
                       study.algorithm_infos(), study_run_keys(study));
    RunnerOptions options;
    options.threads = threads;
    options.stop = stop;
    options.on_run_finished = std::move(on_run);
    Ran ran;
    ran.outcome = run_study_by_precision(study, writer, options,
                                         {{}, {}, [&](const PrecisionRoundStart&) { ++ran.rounds; }});
    return ran;
}

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("mhb_precision_rounds_" + name);
    fs::remove_all(dir);
    return dir;
}

const char* const deterministic_files[] = {"runs.csv",         "curves.csv",       "checkpoints.csv",
                                           "trajectories.csv", "improvements.csv", "study.ini"};

TEST(PrecisionRounds, SameRunsAtOneAndTwoThreadsAndAfterAnInterruption) {
    const PreparedStudy study = make_study();
    const fs::path one = fresh_dir("one");
    const fs::path two = fresh_dir("two");
    const fs::path cut = fresh_dir("cut");
    const Ran first = run_into(one, study, 1);
    EXPECT_FALSE(first.outcome.interrupted);
    EXPECT_GT(first.rounds, 1); // the study is one that needs rounds
    run_into(two, study, 2);
    // Stopped in the middle of the second round, then resumed by a fresh writer.
    std::atomic<bool> stop{false};
    std::int64_t finished = 0;
    const Ran stopped = run_into(cut, study, 2, &stop, [&](std::int64_t, std::int64_t, const RunRecord&) {
        if (++finished == 26)
            stop = true;
    });
    ASSERT_TRUE(stopped.outcome.interrupted);
    EXPECT_FALSE(fs::exists(cut / "runs.csv"));
    const Ran resumed = run_into(cut, study, 1);
    EXPECT_FALSE(resumed.outcome.interrupted);
    EXPECT_GE(resumed.outcome.resumed, 26);
    for (const char* file : deterministic_files) {
        EXPECT_EQ(read_text(one / file), read_text(two / file)) << file;
        EXPECT_EQ(read_text(one / file), read_text(cut / file)) << file;
    }
}

TEST(PrecisionRounds, EachCellStopsWhereTheRuleSaysFromTheFilesAlone) {
    const PreparedStudy study = make_study();
    const fs::path dir = fresh_dir("cells");
    run_into(dir, study, 2);
    const StudyData data = load_study(dir);
    const std::optional<PrecisionRule> rule = precision_rule_of(data.study_text);
    ASSERT_TRUE(rule);
    const StudyIndex index(data);
    const std::string reference = index.algorithms()[default_reference_index(index.algorithms())];
    EXPECT_EQ(reference, "itlbo");
    std::size_t settled = 0;
    std::size_t different_counts = 0;
    for (const std::string& problem : index.problems()) {
        const RunGroup* ref = index.group(problem, reference);
        ASSERT_NE(ref, nullptr);
        std::vector<double> ref_values;
        for (const RunRecord* r : ref->runs)
            ref_values.push_back(compared_value(*r));
        std::size_t most = 0;
        for (const std::string& algorithm : index.algorithms()) {
            if (algorithm == reference)
                continue;
            const RunGroup* group = index.group(problem, algorithm);
            ASSERT_NE(group, nullptr);
            std::vector<double> values;
            for (const RunRecord* r : group->runs)
                values.push_back(compared_value(*r));
            const CellPrecision point = stopping_point(values, &ref_values, true, *rule);
            EXPECT_NE(point.stop, PrecisionStop::needs_runs) << problem << " " << algorithm;
            EXPECT_EQ(static_cast<std::int64_t>(group->runs.size()), point.runs)
                << problem << " " << algorithm;
            if (point.stop == PrecisionStop::precision_reached) {
                EXPECT_LE(point.standard_error, rule->precision);
            }
            settled += point.stop == PrecisionStop::precision_reached ? 1U : 0U;
            different_counts += point.runs != rule->initial ? 1U : 0U;
            most = std::max(most, group->runs.size());
        }
        // The reference ran as many runs as the cell that needed most, and no more.
        EXPECT_EQ(ref->runs.size(), most) << problem;
    }
    EXPECT_GT(settled, 0u);
    EXPECT_GT(different_counts, 0u);
}

TEST(PrecisionRounds, StudyIniKeepsTheRule) {
    const PreparedStudy study = make_study();
    const std::string text = study_ini(study.study);
    EXPECT_NE(text.find("runs = auto\nprecision = 0.25\nmax-runs = 16\ninitial-runs = 4\nround-runs = 3\n"),
              std::string::npos)
        << text;
    Study read;
    std::vector<std::string> errors;
    ASSERT_TRUE(parse_study_file(text, "study.ini", read, errors));
    ASSERT_TRUE(errors.empty()) << errors.front();
    ASSERT_TRUE(read.by_precision);
    EXPECT_EQ(read.runs, 16);
    EXPECT_EQ(read.by_precision->precision, 0.25);
    EXPECT_EQ(read.by_precision->initial, 4);
    EXPECT_EQ(read.by_precision->step, 3);
    EXPECT_EQ(study_ini(prepare_study(read).study), text);
}

} // namespace precision_rounds_test
} // namespace mhb
