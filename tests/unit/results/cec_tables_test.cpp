// The competition's tables and files of a study that follows a CEC protocol, on hand-made run
// records: the errors table's best, worst, median, mean and std by hand (with an error of 5e-9
// counted as 0), the mean ranks, the CEC 2022 U-score on the TR's own example (Table V), the CEC 2017
// score over the four dimensions by hand, and the report of a protocol study writing all of it.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>

#include "results/report/report.hpp"
#include "results/store/csv.hpp"
#include "results/store/study_index.hpp"
#include "results/tables/cec_tables.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

// A run of `algorithm` on cec2017 function `f` at dimension `dimension` whose final error is `error`
// (f* = 100 f), recorded as two improvements: the first evaluation (an error of 1000 + floor(error)),
// then the final value at evaluation 500.
RunRecord cec_run(std::int64_t id, const std::string& algorithm, int f, std::int64_t dimension,
                  std::int64_t index, double error) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = algorithm;
    r.problem = "cec2017:dim=" + std::to_string(dimension) + ",f=" + std::to_string(f);
    r.budget = "evaluations=100*dim";
    r.run_index = index;
    r.seed = static_cast<std::uint64_t>(7 + index); // common random numbers: paired by run index
    r.f_opt = 100.0 * f;
    r.best_f = *r.f_opt + error;
    r.evaluations = 100 * dimension;
    r.best_x.assign(static_cast<std::size_t>(dimension), 0.0);
    r.improvements = ImprovementTrace{};
    r.improvements->points = {{1, *r.f_opt + 1000.0 + std::floor(error)}, {500, r.best_f}};
    r.improvements->last_f = r.best_f;
    return r;
}

// Two algorithms on F1 and F3 at D = 10, three runs each.
StudyData two_function_study() {
    StudyData data;
    data.directory = "/tmp/not-used";
    data.study_text = "algorithms = a\nalgorithms = b\nprotocol = cec2017\n";
    const std::vector<double> a1 = {5e-9, 2.0, 4.0}; // errors 0, 2, 4: mean 2, median 2, std 2
    const std::vector<double> b1 = {1.0, 1.0, 1.0};
    const std::vector<double> a3 = {1.0, 3.0, 8.0}; // mean 4, median 3, std sqrt(13)
    const std::vector<double> b3 = {6.0, 9.0, 9.0};
    std::int64_t id = 0;
    for (int f : {1, 3})
        for (const std::string algorithm : {"a", "b"})
            for (std::int64_t i = 0; i < 3; ++i) {
                const auto& errors = f == 1 ? (algorithm == "a" ? a1 : b1) : (algorithm == "a" ? a3 : b3);
                data.runs.push_back(cec_run(id++, algorithm, f, 10, i, errors[static_cast<std::size_t>(i)]));
            }
    return data;
}

const Table& table_with_id(const std::vector<Table>& tables, const std::string& id) {
    const auto found = std::find_if(tables.begin(), tables.end(), [&](const Table& t) { return t.id == id; });
    if (found == tables.end())
        throw std::logic_error("no table " + id);
    return *found;
}

TEST(CecTables, TheErrorsTableGivesBestWorstMedianMeanStdOfTheErrors) {
    const StudyData data = two_function_study();
    const StudyIndex index(data);
    const auto tables = cec_tables(index, *find_cec_protocol("cec2017"), "a", 0.05);
    const Table& errors = table_with_id(tables, "cec_errors_d10");
    EXPECT_EQ(errors.header, (std::vector<std::string>{"Function", "Algorithm", "Best", "Worst", "Median",
                                                       "Mean", "Std", "vs reference"}));
    ASSERT_EQ(errors.rows.size(), 4u);
    const auto numbers = [&](std::size_t row) {
        std::vector<double> out;
        for (std::size_t c = 2; c <= 6; ++c)
            out.push_back(*errors.rows[row][c].number);
        return out;
    };
    EXPECT_EQ(errors.rows[0][0].text, "F1");
    EXPECT_EQ(errors.rows[0][1].text, "a");
    EXPECT_EQ(numbers(0), (std::vector<double>{0.0, 4.0, 2.0, 2.0, 2.0})); // 5e-9 counts as 0
    EXPECT_EQ(numbers(1), (std::vector<double>{1.0, 1.0, 1.0, 1.0, 0.0}));
    EXPECT_EQ(errors.rows[2][0].text, "F3");
    const std::vector<double> a3 = numbers(2);
    EXPECT_EQ(std::vector<double>(a3.begin(), a3.end() - 1), (std::vector<double>{1.0, 8.0, 3.0, 4.0}));
    EXPECT_NEAR(a3.back(), std::sqrt(13.0), 1e-14);
    // Three paired runs cannot be significant (the exact signed-rank p is at least 0.25): "=".
    EXPECT_EQ(errors.rows[0][7].text, "");
    EXPECT_EQ(errors.rows[1][7].text, "=");
    ASSERT_EQ(errors.footer.size(), 1u);
    EXPECT_EQ(errors.footer[0][7].text, "0/2/0");
    EXPECT_NE(errors.caption.find("this study has 3 runs and MaxFES = 1000 at D = 10, the CEC 2017 protocol "
                                  "asks for 51 runs and MaxFES = 100000"),
              std::string::npos)
        << errors.caption;
}

TEST(CecTables, RanksAreThoseOfTheMeanErrorsPerFunction) {
    const StudyData data = two_function_study();
    const StudyIndex index(data);
    const auto tables = cec_tables(index, *find_cec_protocol("cec2017"), "a", 0.05);
    const Table& ranks = table_with_id(tables, "cec_ranks_d10");
    ASSERT_EQ(ranks.rows.size(), 2u);
    // F1: means a 2, b 1 -> ranks 2, 1; F3: a 4, b 8 -> 1, 2.
    EXPECT_EQ(*ranks.rows[0][1].number, 1.5);
    EXPECT_EQ(*ranks.rows[1][1].number, 1.5);
    EXPECT_EQ(*ranks.rows[0][2].number, 3.0);
    EXPECT_EQ(ranks.rows[0][0].text, "a (reference)");
    EXPECT_EQ(ranks.rows[1][3].text, "0/2/0");
    EXPECT_EQ(ranks.header.size(), 4u); // no U-score column for CEC 2017
    EXPECT_NE(ranks.caption.find("Friedman test of the ranks over the 2 functions"), std::string::npos);
    // No CEC 2017 score without all four of D = 10, 30, 50, 100.
    EXPECT_EQ(
        std::count_if(tables.begin(), tables.end(), [](const Table& t) { return t.id == "cec2017_score"; }),
        0);
}

TEST(CecTables, Cec2017sF2IsReportedButNotRanked) {
    StudyData data = two_function_study();
    for (auto& r : data.runs)
        if (r.problem == "cec2017:dim=10,f=3")
            r.problem = "cec2017:dim=10,f=2";
    const StudyIndex index(data);
    const auto tables = cec_tables(index, *find_cec_protocol("cec2017"), "a", 0.05);
    EXPECT_EQ(table_with_id(tables, "cec_errors_d10").rows.size(), 4u); // F1 and F2, two algorithms
    const Table& ranks = table_with_id(tables, "cec_ranks_d10");
    EXPECT_EQ(ranks.title, "CEC 2017, D = 10: ranks of the mean errors over 1 function");
    EXPECT_EQ(*ranks.rows[0][1].number, 2.0); // F1 alone: a's mean 2 is above b's 1
    EXPECT_NE(ranks.caption.find("F2, which the organisers excluded from the competition, is not ranked."),
              std::string::npos);
}

TEST(CecTables, TheUScoreReproducesTheCec2022Example) {
    // TR 2022, Fig. 11 and Table V: from best to worst, p r q q r p q (seven trials reached 1e-8,
    // in this order of FEterm) then p r q p r (at MaxFES, in this order of error). Scores: P 16, Q 18,
    // R 14.
    std::vector<std::vector<CecTrial>> trials(3);
    const std::string order = "prqqrpqprqpr";
    for (std::size_t i = 0; i < order.size(); ++i) {
        const bool reached = i < 7;
        trials[static_cast<std::size_t>(order[i] - 'p')].push_back(
            {reached, reached ? static_cast<std::int64_t>(100 * (i + 1)) : 1000,
             reached ? 0.0 : static_cast<double>(i)});
    }
    EXPECT_EQ(cec_u_scores(trials), (std::vector<double>{16.0, 18.0, 14.0}));
    // Ties share the mean rank: two algorithms whose trials are all alike score n^2 / 2 each.
    const std::vector<std::vector<CecTrial>> tied = {{{true, 50, 0.0}, {true, 50, 0.0}},
                                                     {{true, 50, 0.0}, {true, 50, 0.0}}};
    EXPECT_EQ(cec_u_scores(tied), (std::vector<double>{2.0, 2.0}));
}

TEST(CecTables, Cec2022RanksCarryTheUScore) {
    StudyData data = two_function_study();
    for (auto& r : data.runs)
        r.problem = "cec2022" + r.problem.substr(7);
    const StudyIndex index(data);
    const auto tables = cec_tables(index, *find_cec_protocol("cec2022"), "a", 0.05);
    const Table& ranks = table_with_id(tables, "cec_ranks_d10");
    ASSERT_EQ(ranks.header.back(), "U-score");
    // F1: a's errors 0 (reached at evaluation 500), 2, 4; b's 1, 1, 1. Worst to best: a4, a2, b1 b1 b1
    // (tied, ranks 3-5: 4 each), a0: a = 1 + 2 + 6 - 6 = 3, b = 12 - 6 = 6. F3: b9 b9 (1.5 each), a8 (3),
    // b6 (4), a3 (5), a1 (6): a = 14 - 6 = 8, b = 7 - 6 = 1. Sums: a 11, b 7.
    EXPECT_EQ(*ranks.rows[0][4].number, 11.0);
    EXPECT_EQ(*ranks.rows[1][4].number, 7.0);
}

TEST(CecTables, TheCec2017ScoreWeighsTheFourDimensions) {
    StudyData data;
    std::int64_t id = 0;
    for (std::int64_t d : {10, 30, 50, 100})
        for (std::int64_t i = 0; i < 2; ++i) {
            data.runs.push_back(cec_run(id++, "a", 1, d, i, 1.0));
            data.runs.push_back(cec_run(id++, "b", 1, d, i, 3.0));
        }
    const StudyIndex index(data);
    const auto tables = cec_tables(index, *find_cec_protocol("cec2017"), "a", 0.05);
    const Table& score = table_with_id(tables, "cec2017_score");
    // SE: a = (0.1 + 0.2 + 0.3 + 0.4) x 1 = 1, b = 3; SR: a = 1, b = 2. Score1 = 50 (1 - (S - S_min) / S):
    // a 50, b 50/3; Score2: a 50, b 25.
    ASSERT_EQ(score.rows.size(), 2u);
    EXPECT_NEAR(*score.rows[0][1].number, 1.0, 1e-14);
    EXPECT_NEAR(*score.rows[1][1].number, 3.0, 1e-14);
    EXPECT_NEAR(*score.rows[0][5].number, 100.0, 1e-12);
    EXPECT_NEAR(*score.rows[1][2].number, 50.0 / 3.0, 1e-12);
    EXPECT_NEAR(*score.rows[1][4].number, 25.0, 1e-12);
    EXPECT_NEAR(*score.rows[1][5].number, 50.0 / 3.0 + 25.0, 1e-12);
    EXPECT_TRUE(score.rows[0][5].bold);
    // One errors and one ranks table per dimension, in order.
    std::vector<std::string> ids;
    for (const auto& t : tables)
        ids.push_back(t.id);
    EXPECT_EQ(ids, (std::vector<std::string>{"cec_errors_d10", "cec_ranks_d10", "cec_errors_d30",
                                             "cec_ranks_d30", "cec_errors_d50", "cec_ranks_d50",
                                             "cec_errors_d100", "cec_ranks_d100", "cec2017_score"}));
}

TEST(CecTables, TheReportOfAProtocolStudyWritesTheTablesAndTheResultFiles) {
    StudyData data = two_function_study();
    data.directory = test_support::fresh_temporary_path("mhb_cec_report_", "two");
    fs::create_directories(data.directory);
    ReportOptions options;
    options.figures = false;
    std::ostringstream console;
    (void)build_report(data, options, console);
    const fs::path report = data.directory / "report";
    for (const char* table : {"cec_errors_d10", "cec_ranks_d10"})
        for (const char* ext : {".md", ".tex", ".csv"})
            EXPECT_TRUE(fs::exists(report / (std::string(table) + ext))) << table << ext;
    // F1 of algorithm a: errors 0 (5e-9), 2, 4 after MaxFES = 1000; before evaluation 500 the first
    // improvement's value, 1000 more.
    EXPECT_EQ(test_support::read_text(report / "cec" / "a_1_10.txt"),
              "1000 1002 1004\n1000 1002 1004\n1000 1002 1004\n1000 1002 1004\n1000 1002 1004\n"
              "1000 1002 1004\n1000 1002 1004\n1000 1002 1004\n0 2 4\n0 2 4\n0 2 4\n0 2 4\n0 2 4\n0 2 4\n");
    for (const char* name : {"a_3_10.txt", "b_1_10.txt", "b_3_10.txt", "README"})
        EXPECT_TRUE(fs::exists(report / "cec" / name)) << name;
    EXPECT_NE(console.str().find("CEC 2017 result files (4, the organisers' layout"), std::string::npos)
        << console.str();
    // The tables are in the combined report too.
    EXPECT_NE(
        test_support::read_text(report / "report.md").find("### CEC 2017, D = 10: error f - f* after MaxFES"),
        std::string::npos);
    // Without the protocol, neither the tables nor the files (a stale cec/ of an earlier report goes).
    data.study_text = "algorithms = a\nalgorithms = b\n";
    std::ostringstream again;
    (void)build_report(data, options, again);
    EXPECT_FALSE(fs::exists(report / "cec"));
    EXPECT_EQ(test_support::read_text(report / "report.md").find("CEC 2017"), std::string::npos);
}

} // namespace
} // namespace mhb
