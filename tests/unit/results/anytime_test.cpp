// The anytime measures (issue 38) against values worked out by hand: the area under the ECDF of
// targets (results/analysis/ecdf_area.hpp) of runs whose improvements are chosen, COCO's percentile
// and simulated restarts (results/analysis/ert_bootstrap.hpp: reproducible with a seed, every length
// a sum of the runs' evaluations, its mean the ERT), the ERT table, and the overhead table from
// wall times (present with timings, absent without).
#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <set>

#include "results/analysis/ecdf_area.hpp"
#include "results/analysis/ert_bootstrap.hpp"
#include "results/analysis/evaluation_time.hpp"
#include "results/tables/anytime_tables.hpp"
#include "results/tables/overhead_table.hpp"

namespace mhb {
namespace {

const std::string anytime_budget = "evaluations=1000";

// A run on `problem` (f* = f_opt) whose best-so-far improves at the given (evaluation, f - f*).
RunRecord anytime_run(const std::string& problem, const std::string& algorithm, double f_opt,
                      const std::vector<std::pair<std::int64_t, double>>& gaps, std::int64_t id) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = algorithm;
    r.problem = problem;
    r.budget = anytime_budget;
    r.run_index = id % 2;
    r.seed = 10 + static_cast<std::uint64_t>(id % 2);
    r.f_opt = f_opt;
    r.evaluations = 1000;
    r.iterations = 10;
    r.best_x = {0.0, 0.0};
    ImprovementTrace trace;
    for (const auto& [evaluation, gap] : gaps)
        trace.points.push_back({evaluation, f_opt + gap});
    trace.last_f = trace.points.back().best_f;
    r.best_f = trace.last_f;
    r.improvements = trace;
    r.curve = {{10, 1000, r.best_f, {}}};
    r.checkpoints = {{1000, r.best_f}};
    return r;
}

// Two problems (f* = 0 and f* = 5), algorithms a and b, two runs each (B = 1000, log10 B = 3):
//   a, run 0: gaps 1e3 at 1, 50 at 10, 0.5 at 100, 1e-9 at 1000: targets 1e2 at 10 (adds 2/3),
//             1e1 and 1e0 at 100 (1/3 each), 1e-1 ... 1e-8 at 1000 (0 each): 4/3 over 11 pairs;
//   a, run 1: gap 200 from evaluation 1: nothing;  so a's area is (4/3) / 22 = 2/33 on each problem.
//   b, run 0 and 1: gap 1e-9 at evaluation 1: every target at once: area 1.
StudyData anytime_study() {
    StudyData data;
    data.directory = "/nonexistent/anytime";
    std::int64_t id = 0;
    for (const auto& [problem, f_opt] :
         std::vector<std::pair<std::string, double>>{{"sphere:dim=2", 0.0}, {"rastrigin:dim=2", 5.0}}) {
        data.runs.push_back(
            anytime_run(problem, "a", f_opt, {{1, 1e3}, {10, 50.0}, {100, 0.5}, {1000, 1e-9}}, id++));
        data.runs.push_back(anytime_run(problem, "a", f_opt, {{1, 200.0}}, id++));
        data.runs.push_back(anytime_run(problem, "b", f_opt, {{1, 1e-9}}, id++));
        data.runs.push_back(anytime_run(problem, "b", f_opt, {{1, 1e-9}}, id++));
    }
    return data;
}

TEST(EcdfArea, IsTheMeanOfEachPairsShareOfTheLogBudget) {
    // log10 1000 = 3: hits at 1, 10, 100 add 3/3, 2/3, 1/3; never and after B add 0.
    EXPECT_NEAR(ecdf_area({1, 10, 100, std::nullopt}, 1000), 0.5, 1e-15);
    EXPECT_NEAR(ecdf_area({1, 2000}, 1000), 0.5, 1e-15);
    EXPECT_EQ(ecdf_area({std::nullopt}, 1000), 0.0);
    EXPECT_EQ(ecdf_area({1, std::nullopt}, 1), 0.5); // one point on the axis: the fraction reached
    EXPECT_THROW(ecdf_area({}, 1000), std::invalid_argument);
    EXPECT_THROW(ecdf_area({1}, 0), std::invalid_argument);
}

TEST(EcdfArea, PerProblemFromTheImprovementsAndPooled) {
    const StudyData data = anytime_study();
    const StudyIndex index(data);
    const std::vector<EcdfAreaGroup> groups = ecdf_areas(index);
    ASSERT_EQ(groups.size(), 3u); // two problems, then pooled
    for (const auto& g : groups) {
        ASSERT_EQ(g.cells.size(), 2u);
        EXPECT_EQ(g.cells[0].algorithm, "a");
        EXPECT_NEAR(g.cells[0].area, 2.0 / 33.0, 1e-15) << g.problem;
        EXPECT_NEAR(g.cells[1].area, 1.0, 1e-15) << g.problem;
    }
    EXPECT_EQ(groups[0].budget, 1000);
    EXPECT_EQ(groups[0].cells[0].pairs, 22u);
    EXPECT_EQ(groups[0].cells[0].reached, 11u); // run 0 reaches every target by evaluation 1000
    EXPECT_TRUE(groups[2].problem.empty());
    EXPECT_EQ(groups[2].problems, 2u);
    EXPECT_EQ(groups[2].cells[1].pairs, 44u);

    const auto table = ecdf_area_table(index);
    ASSERT_TRUE(table.has_value());
    EXPECT_EQ(table->rows.size(), 6u);
    EXPECT_EQ(table->rows[0][5].text, "0.061");
    EXPECT_EQ(table->rows[4][0].text, "all 2 problems");
}

TEST(ErtBootstrap, CocoPercentileAsCocoppsPrctile) {
    // cocopp's prctile: i = p/100 N - 0.5; N = 4.
    const std::vector<double> x = {1, 2, 3, 4};
    EXPECT_EQ(coco_percentile(x, 10), 1.0);          // i = -0.1: the smallest
    EXPECT_NEAR(coco_percentile(x, 30), 1.7, 1e-15); // i = 0.7
    EXPECT_NEAR(coco_percentile(x, 50), 2.5, 1e-15); // i = 1.5
    EXPECT_EQ(coco_percentile(x, 90), 4.0);          // i = 3.1 >= N - 1: the largest
}

TEST(ErtBootstrap, SimulatedRestartsAreSumsOfRunsReproducibleByTheirSeed) {
    // Two successes (100 and 300 evaluations) and a failure that spent 1000: ERT = 1400 / 2 = 700.
    const std::vector<TargetHit> runs = {{true, 100}, {false, 1000}, {true, 300}};
    Rng one(7);
    Rng same(7);
    Rng other(8);
    const std::vector<double> lengths = simulated_run_lengths(runs, 20000, one);
    EXPECT_EQ(lengths, simulated_run_lengths(runs, 20000, same));
    EXPECT_NE(lengths, simulated_run_lengths(runs, 20000, other));
    ASSERT_EQ(lengths.size(), 20000u);
    double sum = 0.0;
    for (double v : lengths) {
        const double last = std::fmod(v, 1000.0); // restarts of 1000 each, then one success
        EXPECT_TRUE(last == 100.0 || last == 300.0) << v;
        sum += v;
    }
    // The mean of a simulated length is the ERT. Restarts K are geometric (a draw fails with
    // probability 1/3): sd(1000 K) = 1000 sqrt(0.75) = 866, so the mean of 20000 is 700 +- 6 (sd).
    EXPECT_NEAR(sum / 20000.0, 700.0, 30.0);
    EXPECT_TRUE(simulated_run_lengths({{false, 10}}, 5, one).empty());
    Rng rng(1);
    const auto ert = ert_interval(runs, rng);
    ASSERT_TRUE(ert.has_value());
    EXPECT_EQ(ert->ert, 700.0);
    // P(length = 100) = P(the first draw is the 100-evaluation success) = 1/3 > 10 %: the 10th
    // percentile is 100.
    EXPECT_EQ(ert->p10, 100.0);
    EXPECT_GT(ert->p90, 1000.0);
    EXPECT_FALSE(ert_interval({{false, 10}}, rng).has_value());
}

TEST(ErtTable, RowsForTheTargetsSomeRunReached) {
    const StudyData data = anytime_study();
    const StudyIndex index(data);
    const auto t = ert_table(index);
    ASSERT_TRUE(t.has_value());
    // Every target is reached on both problems (b at once): 2 problems x 11 targets x 2 algorithms.
    ASSERT_EQ(t->rows.size(), 44u);
    // sphere, target 1e2: a's run 0 at 10, run 1 never (spent 1000): ERT 1010; b at 1: ERT 1, and every
    // simulated restart of b is 1.
    EXPECT_EQ(t->rows[0][2].text, "a");
    EXPECT_EQ(t->rows[0][3].text, "1/2");
    EXPECT_EQ(*t->rows[0][4].number, 1010.0);
    EXPECT_EQ(*t->rows[1][4].number, 1.0);
    EXPECT_EQ(*t->rows[1][5].number, 1.0);
    EXPECT_EQ(*t->rows[1][6].number, 1.0);
    EXPECT_EQ(*ert_table(index)->rows[0][6].number, *t->rows[0][6].number); // seeded: the same each time
}

TEST(OverheadTable, MedianTimePerEvaluationOnlyWithTimings) {
    StudyData data = anytime_study();
    for (auto& r : data.runs)
        r.algorithm = r.algorithm == "b" ? "random-search" : r.algorithm;
    const StudyIndex index(data);
    EXPECT_FALSE(overhead_table(index, {}).has_value());
    // 1000 evaluations per run: a's runs on sphere 0.004 and 0.002 s (4 and 2 us per evaluation,
    // median 3); random-search's 0.001 s each (1 us).
    std::map<std::int64_t, double> wall = {{0, 0.004}, {1, 0.002}, {2, 0.001}, {3, 0.001}};
    const auto times = evaluation_times(index, wall);
    ASSERT_EQ(times.size(), 2u); // only the sphere's runs were timed
    EXPECT_NEAR(times[0].median_microseconds, 3.0, 1e-12);
    EXPECT_EQ(times[0].dimension, 2);
    EXPECT_EQ(times[0].runs, 2u);
    const auto t = overhead_table(index, wall);
    ASSERT_TRUE(t.has_value());
    ASSERT_EQ(t->rows.size(), 2u);
    EXPECT_NEAR(*t->rows[0][4].number, 3.0, 1e-12);
    EXPECT_NEAR(*t->rows[1][4].number, 1.0, 1e-12);
    EXPECT_EQ(t->rows[1][2].text, "random-search");
}

} // namespace
} // namespace mhb
