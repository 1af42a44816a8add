// What the comparison tables show (issues 12 and 21): the problems x algorithms table shows the median
// (IQR), the statistic its rank-test markers are about, bolds the best median, and ends in a w/t/l
// row that counts the markers; the summary's budget columns take every algorithm of a problem at
// the same evaluation counts.
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "results/store/study_index.hpp"
#include "results/tables/comparison_tables.hpp"
#include "results/text/csv_table.hpp"
#include "results/text/markdown_table.hpp"

namespace mhb {
namespace {

RunRecord comparison_run(const std::string& algorithm, const std::string& problem, const std::string& budget,
                         std::int64_t index, double f) {
    static std::int64_t id = 0;
    RunRecord r;
    r.run_id = id++;
    r.algorithm = algorithm;
    r.problem = problem;
    r.budget = budget;
    r.run_index = index;
    r.seed = 500 + static_cast<std::uint64_t>(index); // common random numbers: paired
    r.best_f = f;
    r.evaluations = 100;
    r.iterations = 2;
    r.checkpoints = {{1, 4 * f}, {100, f}};
    return r;
}

const Table& table_named(const std::vector<Table>& tables, const std::string& id) {
    for (const auto& t : tables)
        if (t.id == id)
            return t;
    throw std::logic_error("no table " + id);
}

std::size_t column_named(const Table& t, const std::string& header) {
    for (std::size_t c = 0; c < t.header.size(); ++c)
        if (t.header[c] == header)
            return c;
    throw std::logic_error("no column " + header + " in " + t.id);
}

// Twelve paired runs on three problems: tlbo better than itlbo in every pair on "better", mixed on
// "mixed", and on "outlier" worse in 11 pairs of 12, while one run of itlbo ends at 1000: its mean
// (84.25) is far above tlbo's (2), its median (1) below tlbo's (2).
StudyData markers_study() {
    StudyData data;
    data.directory = "/nonexistent/markers";
    for (std::int64_t i = 0; i < 12; ++i) {
        const double base = 1.0 + static_cast<double>(i);
        data.runs.push_back(comparison_run("itlbo", "better", "iterations=2", i, base));
        data.runs.push_back(comparison_run("tlbo", "better", "iterations=2", i, base - 0.5));
        data.runs.push_back(comparison_run("itlbo", "mixed", "iterations=2", i, base));
        data.runs.push_back(
            comparison_run("tlbo", "mixed", "iterations=2", i, base + (i % 2 == 0 ? 0.5 : -0.5)));
        data.runs.push_back(comparison_run("itlbo", "outlier", "iterations=2", i, i == 11 ? 1000.0 : 1.0));
        data.runs.push_back(comparison_run("tlbo", "outlier", "iterations=2", i, 2.0));
    }
    return data;
}

TEST(ComparisonTable, ShowsTheMedianTheMarkersAreAboutAndCountsThem) {
    const StudyData data = markers_study(); // the index points into it
    const StudyIndex index(data);
    const auto tables = comparison_tables(index, {"itlbo", 0.05, {0.01, 0.1, 1.0}});
    const Table& c = table_named(tables, "comparison");
    EXPECT_NE(c.title.find("median (IQR)"), std::string::npos);
    const std::size_t tlbo = column_named(c, "tlbo");
    const std::size_t itlbo = column_named(c, "itlbo (reference)");
    ASSERT_EQ(c.rows.size(), 3u);
    EXPECT_EQ(c.rows[0][tlbo].marker, "+");
    EXPECT_EQ(c.rows[1][tlbo].marker, "=");
    // The outlier problem: tlbo's mean is 42 times lower, yet the rank test says worse, and the cell
    // says why: median 2 (IQR 0) against the reference's 1, which is the bold one.
    const TableCell& worse = c.rows[2][tlbo];
    EXPECT_EQ(worse.marker, "-");
    EXPECT_EQ(*worse.number, 2.0);
    EXPECT_EQ(*worse.spread, 0.0);
    EXPECT_FALSE(worse.bold);
    EXPECT_TRUE(c.rows[2][itlbo].bold);
    EXPECT_EQ(*c.rows[2][itlbo].number, 1.0);
    EXPECT_EQ(worse.text, "2.0 (0.0) -"); // this column's medians and IQRs are halves: one decimal
    EXPECT_NE(c.caption.find("lowest median in bold"), std::string::npos);

    // w/t/l under the table: one win, one tie, one loss, as the markers above say.
    ASSERT_EQ(c.footer.size(), 1u);
    EXPECT_EQ(c.footer[0][0].text, "w/t/l");
    EXPECT_EQ(c.footer[0][tlbo].text, "1/1/1");
    EXPECT_EQ(c.footer[0][itlbo].text, ""); // the reference is not compared with itself
    const std::string markdown = render_markdown(c);
    EXPECT_NE(markdown.find("| w/t/l |  | 1/1/1 |"), std::string::npos) << markdown;
    EXPECT_EQ(render_csv(c).find("w/t/l"), std::string::npos); // CSV rows are all of one kind

    // The tests table: the same counts from its Result column.
    const Table& t = table_named(tables, "tests");
    const std::size_t result = column_named(t, "Result");
    std::size_t w = 0;
    std::size_t ties = 0;
    std::size_t l = 0;
    for (const auto& row : t.rows) {
        w += row[result].text == "+" ? 1U : 0U;
        ties += row[result].text == "=" ? 1U : 0U;
        l += row[result].text == "-" ? 1U : 0U;
    }
    ASSERT_EQ(t.footer.size(), 1u);
    EXPECT_EQ(t.footer[0][column_named(t, "Algorithm")].text, "tlbo");
    EXPECT_EQ(t.footer[0][result].text,
              std::to_string(w) + "/" + std::to_string(ties) + "/" + std::to_string(l));
    EXPECT_EQ(t.footer[0][result].text, "1/1/1");
}

// Runs that stop at different counts: "a" reaches its end after 400 evaluations, "b" after 1000.
RunRecord budget_run(const std::string& algorithm, const std::string& budget, std::int64_t index) {
    RunRecord r = comparison_run(algorithm, "sphere:dim=2", budget, index, 0.0);
    if (algorithm == "a") {
        r.evaluations = 400;
        r.best_f = 5.0;
        r.checkpoints = {{1, 100.0}, {10, 50.0}, {100, 20.0}, {400, 5.0}};
    } else {
        r.evaluations = 1000;
        r.best_f = 2.0;
        r.checkpoints = {{1, 100.0}, {10, 60.0}, {100, 30.0}, {1000, 2.0}};
        // Exact improvements where the run recorded them: these, not the grid, give its values.
        ImprovementTrace trace;
        trace.points = {{1, 100.0}, {7, 55.0}, {90, 25.0}, {950, 2.0}};
        trace.last_f = 2.0;
        r.improvements = trace;
    }
    return r;
}

std::vector<double> budget_medians(const Table& summary, std::size_t row) {
    std::vector<double> out;
    for (std::size_t c = 0; c < summary.header.size(); ++c)
        if (summary.header[c].rfind("Median at", 0) == 0)
            out.push_back(*summary.rows[row][c].number);
    return out;
}

TEST(SummaryBudgetColumns, OneEvaluationCountPerProblemForEveryAlgorithm) {
    for (const std::string budget : {"evaluations=1000", "iterations=50"}) {
        // With an evaluation budget, E is it; without, the most any run on the problem spent:
        // 1000 either way, so "a" and "b" are compared at 10, 100 and 1000 evaluations.
        StudyData data;
        data.directory = "/nonexistent/budget";
        for (std::int64_t i = 0; i < 3; ++i) {
            data.runs.push_back(budget_run("a", budget, i));
            data.runs.push_back(budget_run("b", budget, i));
        }
        const StudyIndex index(data);
        const auto tables = comparison_tables(index, {"a", 0.05, {0.01, 0.1, 1.0}});
        const Table& s = table_named(tables, "summary");
        const std::vector<std::string> headers(s.header.end() - 3, s.header.end());
        EXPECT_EQ(headers, (std::vector<std::string>{"Median at 10 evals (1%)", "Median at 100 evals (10%)",
                                                     "Median at 1000 evals (100%)"}))
            << budget;
        // "a": the grid's 50 at 10 and 20 at 100; at 1000 its final 5, since it stopped at 400.
        EXPECT_EQ(budget_medians(s, 0), (std::vector<double>{50.0, 20.0, 5.0})) << budget;
        // "b": its improvements, 55 (at 7) and 25 (at 90), then 2.
        EXPECT_EQ(budget_medians(s, 1), (std::vector<double>{55.0, 25.0, 2.0})) << budget;
        EXPECT_NE(s.caption.find("a run that stopped earlier counts with its final value"),
                  std::string::npos);
    }
}

TEST(SummaryBudgetColumns, ProblemsWithDifferentCountsGetAColumnOfE) {
    StudyData data;
    data.directory = "/nonexistent/budget";
    for (std::int64_t i = 0; i < 2; ++i) {
        data.runs.push_back(budget_run("a", "iterations=50", i));
        data.runs.push_back(budget_run("b", "iterations=50", i));
        RunRecord other = budget_run("a", "iterations=50", i);
        other.problem = "rastrigin:dim=2"; // only "a", which spends 400
        data.runs.push_back(other);
    }
    const StudyIndex index(data);
    const auto tables = comparison_tables(index, {"a", 0.05, {0.01, 0.1, 1.0}});
    const Table& s = table_named(tables, "summary");
    EXPECT_EQ(s.header.back(), "E (evaluations)");
    EXPECT_EQ(s.header[s.header.size() - 4], "Median at 1% of E");
    EXPECT_EQ(*s.rows[0][s.header.size() - 1].number, 1000.0);
    EXPECT_EQ(*s.rows[2][s.header.size() - 1].number, 400.0);
    EXPECT_NE(s.caption.find("E per problem: 400 on rastrigin:dim=2, 1000 on sphere:dim=2."),
              std::string::npos)
        << s.caption;
}

// Degenerate tests are named where the tests are: on "tied" every run of both algorithms ends at
// 0 (every value the same: the rank-sum test has no variance; every paired difference zero: the
// signed-rank test has nothing to rank), and the tables show z = 0, p = 1, '=' and say why.
TEST(ComparisonTables, CaptionsSayWhenATestIsDegenerate) {
    StudyData data;
    data.directory = "/nonexistent/tied";
    for (std::int64_t i = 0; i < 6; ++i) {
        data.runs.push_back(comparison_run("itlbo", "tied", "iterations=2", i, 0.0));
        data.runs.push_back(comparison_run("tlbo", "tied", "iterations=2", i, 0.0));
        data.runs.push_back(comparison_run("itlbo", "spread", "iterations=2", i, static_cast<double>(i)));
        data.runs.push_back(
            comparison_run("tlbo", "spread", "iterations=2", i, static_cast<double>(i) + 0.5));
    }
    const StudyIndex index(data);
    const auto tables = comparison_tables(index, {"itlbo", 0.05, {1.0}});
    const Table& tests = table_named(tables, "tests");
    std::size_t tied_rows = 0;
    for (const auto& row : tests.rows)
        if (row[0].text == "tied") {
            ++tied_rows;
            EXPECT_EQ(*row[column_named(tests, "p")].number, 1.0);
            EXPECT_EQ(*row[column_named(tests, "Signed-rank p")].number, 1.0);
            EXPECT_EQ(row[column_named(tests, "Result")].text, "=");
        }
    EXPECT_EQ(tied_rows, 1U);
    for (const std::string id : {"tests", "comparison"}) {
        const std::string& caption = table_named(tables, id).caption;
        EXPECT_NE(
            caption.find("In 1 comparison every value of both samples is the same: the rank-sum test has "
                         "no variance there"),
            std::string::npos)
            << id << ": " << caption;
        EXPECT_NE(caption.find("In 1 comparison every paired difference is zero"), std::string::npos)
            << id << ": " << caption;
    }
    // Without a degenerate test the captions say nothing of it.
    StudyData plain;
    for (const auto& r : data.runs)
        if (r.problem == "spread")
            plain.runs.push_back(r);
    const auto plain_tables = comparison_tables(StudyIndex(plain), {"itlbo", 0.05, {1.0}});
    EXPECT_EQ(table_named(plain_tables, "tests").caption.find("every value of both samples"),
              std::string::npos);
}

} // namespace
} // namespace mhb
