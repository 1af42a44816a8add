// The relative-gap table (results/tables/relative_gap_table.hpp) and its data
// (results/analysis/relative_gaps.hpp) from a small study of hand-made runs whose gaps are chosen,
// so that every median and success rate is known by hand: built only for a budget with a relative
// target and two or more problems with a known, non-zero f*; failed runs and runs at +inf; the
// short problem names; the report's files; and, where matplotlib is, its figure.
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>

#include "results/analysis/relative_gaps.hpp"
#include "results/report/report.hpp"
#include "results/store/csv.hpp"
#include "results/tables/relative_gap_table.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

const std::string gap_budget = "evaluations=100,relative_target=1e-06";
const std::string gap_steady = "pmsm:model=steady,noise_i=0.02";
const std::string gap_output = "pmsm:model=output,noise_i=0.02";
const std::string gap_fluxmap = "fluxmap";
const std::string gap_sphere = "sphere:dim=2"; // f* = 0: left out

// A run whose final value lies `gap` x |f*| above f*; `reached`: it met the study's target.
RunRecord gap_run(const std::string& problem, const std::string& algorithm, std::int64_t index, double f_opt,
                  double gap, bool reached) {
    static std::int64_t id = 0;
    RunRecord r;
    r.run_id = id++;
    r.algorithm = algorithm;
    r.problem = problem;
    r.budget = gap_budget;
    r.run_index = index;
    r.seed = 500 + static_cast<std::uint64_t>(index); // common random numbers: paired
    r.f_opt = f_opt;
    r.best_f = f_opt + gap * std::fabs(f_opt);
    r.evaluations = reached ? 60 : 100;
    r.iterations = 2;
    if (reached)
        r.evaluations_to_target = 60;
    r.best_x = {0.1, 0.2};
    r.curve = {{0, 50, r.best_f + 1.0, {}}, {2, r.evaluations, r.best_f, {}}};
    r.checkpoints = {{1, r.best_f + 2.0}, {r.evaluations, r.best_f}};
    return r;
}

RunRecord gap_failed(const std::string& problem, const std::string& algorithm, std::int64_t index) {
    RunRecord r = gap_run(problem, algorithm, index, 1.0, 0.0, false);
    r.ok = false;
    r.message = "the problem returned NaN at evaluation 7";
    r.best_f = std::numeric_limits<double>::quiet_NaN();
    r.curve.clear();
    r.checkpoints.clear();
    return r;
}

// Four runs of `a` and `b` on each problem:
//   steady  (f* = 200): a gaps 0, 1e-7, 3e-7 (reached), 1e-3: median 2e-7, success 0.75;
//                       b gaps 1e-2, 2e-2, 4e-2 and a failed run: median 2e-2, success 0.
//   output  (f* = 4):   a gaps 0.1, 0.2, 0.3, 0.5: median 0.25, success 0; b: every run failed.
//   fluxmap (f* = 36):  a gaps -1e-13 (a best-known f* bettered), 0, 1e-9, 2e-9, all reached:
//                       median 5e-10, success 1; b gaps 1e-3, 2e-3, +inf, +inf: median +inf.
//   sphere  (f* = 0):   left out.
StudyData gap_study(const std::string& budget = gap_budget) {
    StudyData data;
    data.directory = "/nonexistent/gaps";
    data.algorithms = {{"a", "A", "a:x=1"}, {"b", "B", "b:x=1"}};
    const double infinite = std::numeric_limits<double>::infinity();
    const double steady_a[] = {0.0, 1e-7, 3e-7, 1e-3};
    const double steady_b[] = {1e-2, 2e-2, 4e-2};
    const double output_a[] = {0.1, 0.2, 0.3, 0.5};
    const double flux_a[] = {-1e-13, 0.0, 1e-9, 2e-9};
    const double flux_b[] = {1e-3, 2e-3, infinite, infinite};
    for (std::int64_t i = 0; i < 4; ++i) {
        const auto k = static_cast<std::size_t>(i);
        data.runs.push_back(gap_run(gap_steady, "a", i, 200.0, steady_a[k], k < 3));
        data.runs.push_back(i < 3 ? gap_run(gap_steady, "b", i, 200.0, steady_b[k], false)
                                  : gap_failed(gap_steady, "b", i));
    }
    for (std::int64_t i = 0; i < 4; ++i) {
        data.runs.push_back(gap_run(gap_output, "a", i, 4.0, output_a[static_cast<std::size_t>(i)], false));
        data.runs.push_back(gap_failed(gap_output, "b", i));
    }
    for (std::int64_t i = 0; i < 4; ++i) {
        data.runs.push_back(gap_run(gap_fluxmap, "a", i, 36.0, flux_a[static_cast<std::size_t>(i)], true));
        data.runs.push_back(gap_run(gap_fluxmap, "b", i, 36.0, flux_b[static_cast<std::size_t>(i)], false));
    }
    for (std::int64_t i = 0; i < 4; ++i) {
        for (const char* algorithm : {"a", "b"}) {
            RunRecord r = gap_run(gap_sphere, algorithm, i, 1.0, 1.0, false);
            r.f_opt = 0.0;
            data.runs.push_back(std::move(r));
        }
    }
    for (auto& r : data.runs)
        r.budget = budget;
    return data;
}

TEST(RelativeGaps, MediansAndSuccessRatesByHand) {
    const StudyData data = gap_study();
    const StudyIndex index(data, gap_budget);
    const auto gaps = relative_gaps(index);
    ASSERT_TRUE(gaps.has_value());
    EXPECT_EQ(gaps->problems, (std::vector<std::string>{gap_steady, gap_output, gap_fluxmap})); // study order
    EXPECT_EQ(gaps->names, (std::vector<std::string>{"pmsm model=steady", "pmsm model=output", "fluxmap"}));
    EXPECT_EQ(gaps->f_opt, (std::vector<double>{200.0, 4.0, 36.0}));
    EXPECT_EQ(gaps->left_out, (std::vector<std::string>{gap_sphere}));
    ASSERT_EQ(gaps->algorithms, (std::vector<std::string>{"a", "b"}));
    const auto& a = gaps->cells[0];
    const auto& b = gaps->cells[1];
    EXPECT_NEAR(a[0].median, 2e-7, 1e-15);
    EXPECT_EQ(a[0].reached, 3u);
    EXPECT_EQ(a[0].success_rate(), 0.75);
    EXPECT_NEAR(b[0].median, 2e-2, 1e-15);
    EXPECT_EQ(b[0].runs, 3u);
    EXPECT_EQ(b[0].failed, 1u);
    EXPECT_EQ(b[0].success_rate(), 0.0); // the failed run counts as unsuccessful
    EXPECT_NEAR(a[1].median, 0.25, 1e-15);
    EXPECT_EQ(a[1].success_rate(), 0.0);
    EXPECT_TRUE(std::isnan(b[1].median)); // every run failed
    EXPECT_EQ(b[1].failed, 4u);
    EXPECT_EQ(b[1].success_rate(), 0.0);
    EXPECT_NEAR(a[2].median, 5e-10, 1e-15);
    EXPECT_EQ(a[2].success_rate(), 1.0);
    EXPECT_EQ(b[2].median, std::numeric_limits<double>::infinity()); // +inf: the largest value
    // One run's gap, a negative f* by its magnitude.
    RunRecord negative;
    negative.f_opt = -50.0;
    negative.best_f = -49.5;
    EXPECT_EQ(relative_gap(negative), 0.01);
    negative.f_opt = 0.0;
    EXPECT_TRUE(std::isnan(relative_gap(negative)));

    const std::string csv = relative_gap_medians_csv(index, *gaps);
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "problem,name,algorithm,label,f_opt,runs,failed,median_relative_gap,reached,success_rate");
    EXPECT_NE(csv.find("\n\"pmsm:model=output,noise_i=0.02\",pmsm model=output,b,B,4,0,4,,0,0\n"),
              std::string::npos)
        << csv;
    EXPECT_NE(csv.find("\nfluxmap,fluxmap,b,B,36,4,0,inf,0,0\n"), std::string::npos) << csv;
}

TEST(RelativeGaps, TheTableSaysWhatItsNumbersAre) {
    const StudyData data = gap_study();
    const StudyIndex index(data, gap_budget);
    const Table t = relative_gap_table(index, *relative_gaps(index));
    EXPECT_EQ(t.id, "relative_gaps");
    EXPECT_EQ(t.header, (std::vector<std::string>{
                            "Algorithm", "pmsm model=steady: median gap", "pmsm model=steady: success",
                            "pmsm model=output: median gap", "pmsm model=output: success",
                            "fluxmap: median gap", "fluxmap: success"}));
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0][0].text, "A"); // the label
    EXPECT_NEAR(*t.rows[0][1].number, 2e-7, 1e-15);
    EXPECT_TRUE(t.rows[0][1].bold); // the lowest median of the problem
    EXPECT_FALSE(t.rows[1][1].bold);
    EXPECT_EQ(*t.rows[0][2].number, 0.75);
    EXPECT_EQ(*t.rows[1][2].number, 0.0);
    EXPECT_EQ(t.rows[1][3].text, "no successful run (4 failed)");
    EXPECT_EQ(*t.rows[1][4].number, 0.0);
    EXPECT_EQ(*t.rows[1][5].number, std::numeric_limits<double>::infinity());
    for (const char* part :
         {"Relative gap (f - f*) / |f*| of each run's final best value, its median over the 4 runs",
          "runs that reached the study's target, f - f* <= 1e-06 x |f*|, a relative target, over all runs",
          "pmsm model=steady (pmsm:model=steady,noise_i=0.02): f* = 200", "fluxmap (fluxmap): f* = 36",
          "Left out, having no known, non-zero f*: sphere:dim=2.", "5 failed runs left out"})
        EXPECT_NE(t.caption.find(part), std::string::npos) << part << "\n" << t.caption;
}

TEST(RelativeGaps, OnlyForARelativeTargetAndTwoProblemsWithANonZeroOptimum) {
    const StudyData absolute = gap_study("evaluations=100,target=1e-06");
    EXPECT_FALSE(relative_gaps(StudyIndex(absolute, "evaluations=100,target=1e-06")).has_value());
    const StudyData none = gap_study("evaluations=100");
    EXPECT_FALSE(relative_gaps(StudyIndex(none, "evaluations=100")).has_value());
    StudyData one = gap_study();
    std::erase_if(one.runs,
                  [](const RunRecord& r) { return r.problem == gap_steady || r.problem == gap_output; });
    EXPECT_FALSE(relative_gaps(StudyIndex(one, gap_budget)).has_value()); // fluxmap alone (sphere has f* = 0)
}

TEST(RelativeGaps, ShortNamesTellTheProblemsApart) {
    EXPECT_EQ(short_problem_names({"bbob:dim=2,f=1", "bbob:dim=5,f=1", "fluxmap:model=syrm"}),
              (std::vector<std::string>{"bbob dim=2", "bbob dim=5", "fluxmap"}));
    EXPECT_EQ(short_problem_names({"pmsm:load=2,speed=2500", "pmsm:load=3,speed=2000"}),
              (std::vector<std::string>{"pmsm load=2,speed=2500", "pmsm load=3,speed=2000"}));
    // A key one problem lacks names the other; two named alike keep their specs.
    EXPECT_EQ(short_problem_names({"fluxmap", "fluxmap:model=syrm"}),
              (std::vector<std::string>{"fluxmap", "fluxmap model=syrm"}));
}

fs::path gap_report(const std::string& name, bool figures) {
    const fs::path dir = mhb::test_support::fresh_temporary_path("mhb_relative_gaps_", name);
    ReportOptions options;
    options.out_dir = dir;
    options.figures = figures;
    options.plot_script = fs::path(MHB_SOURCE_DIR) / "scripts" / "plot_study.py";
    std::ostringstream console;
    build_report(gap_study(), options, console);
    return dir;
}

TEST(RelativeGaps, TheReportWritesTheTableItsDataAndTheirDescription) {
    const fs::path dir = gap_report("files", false);
    const CsvTable table = read_csv(dir / "relative_gaps.csv");
    ASSERT_EQ(table.rows.size(), 2u);
    EXPECT_EQ(table.number(0, table.column("pmsm model=steady: success")), 0.75);
    const CsvTable data = read_csv(dir / "relative_gap_medians.csv");
    EXPECT_EQ(data.rows.size(), 6u); // 3 problems x 2 algorithms
    const std::string readme = mhb::test_support::read_text(dir / "README.md");
    EXPECT_NE(readme.find("### relative_gap_medians.csv"), std::string::npos);
    // The summary says its target is relative too.
    EXPECT_NE(
        mhb::test_support::read_text(dir / "summary.md").find("f - f* <= 1e-06 x |f*|, a relative target"),
        std::string::npos);
}

// Slow: matplotlib takes seconds to start.
TEST(SlowRelativeGaps, TheFigureIsDrawnWhereMatplotlibIs) {
    if (!find_matplotlib_python(ReportOptions().python_candidates))
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = gap_report("figure", true);
    for (const char* ext : {".pdf", ".png"}) // no SVG since issue 37: the page shows the PNG
        EXPECT_GT(fs::file_size(dir / "figures" / (std::string("relative_gaps") + ext)), 1000u) << ext;
}

} // namespace
} // namespace mhb
