// `mhbench report`'s library side on a small synthetic study (hand-made RunRecords, so no
// optimiser is involved): the paper's tables carry the right numbers, every output file matches its
// golden copy in tests/data/golden/ (regenerate with MHB_UPDATE_GOLDEN=1 after a deliberate change
// and review the diff), the LaTeX compiles where a TeX engine exists, figures are drawn or skipped
// with one clear line, and bad options or damaged directories give clear errors.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include "results/analysis/critical_difference.hpp"
#include "results/report/report.hpp"
#include "results/store/csv.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

const std::vector<std::string> report_algorithms = {"itlbo", "tlbo", "pso"};
const std::vector<double> truth = {0.330, 0.00324, 0.00324, 0.0776};

// PMSM runs: final f = base + step * i (i = 0..4), so ITLBO's mean is 4.02 and std
// 0.01 * sqrt(10 / 4) = 0.015811388 by hand; f* = 3.9.
RunRecord pmsm_run(std::size_t a, std::int64_t i, std::int64_t id) {
    const double base[] = {4.0, 5.0, 5.5};
    const double step[] = {0.01, 0.2, 0.3};
    const std::int64_t evaluations[] = {1200, 600, 300};
    RunRecord r;
    r.run_id = id;
    r.algorithm = report_algorithms[a];
    r.problem = "pmsm:load=2,speed=2500";
    r.budget = "iterations=150";
    r.run_index = i;
    r.seed = static_cast<std::uint64_t>(1000 + id);
    r.best_f = base[a] + step[a] * static_cast<double>(i);
    r.f_opt = 3.9;
    r.evaluations = evaluations[a];
    r.iterations = 2;
    const double ad = static_cast<double>(a);
    const double id_ = static_cast<double>(i);
    r.best_x = {0.33 + 0.001 * (ad + 1.0) * (id_ - 1.0), 0.00324 * (1.0 + 0.01 * ad), 0.00324 + 1e-6 * id_,
                0.0776 + 0.0001 * id_};
    r.parameter_names = {"Rs", "Ld", "Lq", "psi"};
    r.true_parameters = truth;
    r.x_opt = {0.331, 0.003245, 0.003238, 0.07762};
    for (std::int64_t it = 0; it <= 2; ++it) {
        std::vector<double> x = r.best_x;
        for (auto& v : x)
            v *= 1.0 + 0.1 * static_cast<double>(2 - it);
        r.curve.push_back(
            {it, r.evaluations / 3 * (it + 1), r.best_f * static_cast<double>(1 << (2 - it)), x});
    }
    r.checkpoints = {{1, r.best_f * 8}, {10, r.best_f * 4}, {100, r.best_f * 2}, {r.evaluations, r.best_f}};
    return r;
}

// Sphere runs: f = 1e-3 (a + 1) (i + 1); the target is reached by runs with i < 3 - a.
RunRecord sphere_run(std::size_t a, std::int64_t i, std::int64_t id) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = report_algorithms[a];
    r.problem = "sphere:dim=2";
    r.budget = "iterations=150";
    r.run_index = i;
    r.seed = static_cast<std::uint64_t>(2000 + id);
    r.best_f = 1e-3 * static_cast<double>(a + 1) * static_cast<double>(i + 1);
    r.f_opt = 0.0;
    r.evaluations = 1000;
    r.iterations = 2;
    if (i < 3 - static_cast<std::int64_t>(a))
        r.evaluations_to_target = 200 + 100 * i;
    r.best_x = {0.01, -0.02};
    for (std::int64_t it = 0; it <= 2; ++it)
        r.curve.push_back({it, 1000 / 3 * (it + 1), r.best_f * static_cast<double>(10 * (2 - it) + 1), {}});
    r.checkpoints = {{10, r.best_f * 100}, {100, r.best_f * 10}, {1000, r.best_f}};
    return r;
}

fs::path make_study(const std::string& name) {
    // The process id keeps tests that CTest runs in parallel (one process each) apart.
    const fs::path dir = mhb::test_support::fresh_temporary_path("mhb_report_test_", name);
    // The paper's protocol at the paper's budget: the PMSM tables are its Tables 2-4.
    StudyWriter writer(dir, "[study]\nname=synthetic\nprotocol = pmsm-paper\n", "threads=1\n",
                       {"Rs", "Ld", "Lq", "psi"}, false);
    std::int64_t id = 0;
    for (std::size_t a = 0; a < report_algorithms.size(); ++a)
        for (std::int64_t i = 0; i < 5; ++i)
            writer.append(pmsm_run(a, i, id++), 0.01);
    for (std::size_t a = 0; a < report_algorithms.size(); ++a)
        for (std::int64_t i = 0; i < 5; ++i)
            writer.append(sphere_run(a, i, id++), 0.01);
    writer.finish();
    return dir;
}

using mhb::test_support::read_text;

ReportOptions no_figures() {
    ReportOptions options;
    options.figures = false;
    return options;
}

class Report : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        study_dir_ = make_study("fixed");
        std::ostringstream console;
        ReportOptions options = no_figures();
        options.console_tables = true; // --tables: the console shows every table too
        build_report(load_study(study_dir_), options, console);
        console_ = console.str();
    }
    static fs::path study_dir_;
    static std::string console_;
};
fs::path Report::study_dir_;
std::string Report::console_;

TEST_F(Report, Table2CarriesMeasuredAndPublishedFitness) {
    const CsvTable t = read_csv(study_dir_ / "report" / "table2_fitness.csv");
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_EQ(t.rows[0][t.column("Algorithm")], "itlbo");
    EXPECT_NEAR(t.number(0, t.column("Mean f")), 4.02, 1e-12);                // by hand, see pmsm_run
    EXPECT_NEAR(t.number(0, t.column("Std f")), 0.015811388300841896, 1e-12); // 0.01 sqrt(2.5)
    EXPECT_EQ(t.number(0, t.column("Paper mean")), 3.9904);                   // the paper's Table 2
    EXPECT_EQ(t.number(1, t.column("Paper std")), 1.6258);
    EXPECT_EQ(t.number(2, t.column("Paper mean")), 5.5904);
    EXPECT_EQ(t.number(0, t.column("Evaluations (mean)")), 1200.0);
    EXPECT_NEAR(t.number(0, t.column("Mean gap f - f*")), 4.02 - 3.9, 1e-12);
    EXPECT_EQ(t.number(0, t.column("f*")), 3.9);
    EXPECT_NE(console_.find("### Table 2: Fitness of different algorithms"), std::string::npos);
    // The best mean is bold, with the 4 significant digits of its column.
    EXPECT_NE(console_.find("**4.020**"), std::string::npos);
}

TEST_F(Report, Table3CarriesParametersThetaStarAndPaperValues) {
    const CsvTable t = read_csv(study_dir_ / "report" / "table3_parameters.csv");
    const auto find = [&](const std::string& who, const std::string& what) {
        for (std::size_t r = 0; r < t.rows.size(); ++r)
            if (t.rows[r][0] == who && t.rows[r][1] == what)
                return r;
        ADD_FAILURE() << who << " / " << what << " missing";
        return std::size_t{0};
    };
    EXPECT_EQ(t.number(find("True value", "value"), t.column("Rs")), 0.33);
    EXPECT_EQ(t.number(find("theta* (least squares)", "value"), t.column("Ld")), 0.003245);
    // ITLBO's Rs over i = 0..4: 0.33 + 0.001 (i - 1), mean 0.331, error 100 * 0.001 / 0.33 %.
    EXPECT_NEAR(t.number(find("itlbo", "identified (mean)"), t.column("Rs")), 0.331, 1e-12);
    EXPECT_NEAR(t.number(find("itlbo", "error % vs true"), t.column("Rs")), 100.0 * 0.001 / 0.33, 1e-9);
    EXPECT_NEAR(t.number(find("itlbo", "deviation % from theta*"), t.column("Rs")), 0.0, 1e-9);
    EXPECT_EQ(t.number(find("tlbo", "paper identified"), t.column("Ld")), 0.00363); // Table 3
    EXPECT_EQ(t.number(find("pso", "paper |error| %"), t.column("psi")), 2.1);
    // One condition: no table of conditions side by side (Table 4 would repeat Table 3).
    EXPECT_FALSE(fs::exists(study_dir_ / "report" / "table4_conditions.csv"));
}

TEST_F(Report, StatisticsTablesNameTheirTests) {
    const CsvTable tests = read_csv(study_dir_ / "report" / "tests.csv");
    ASSERT_EQ(tests.rows.size(), 4u); // two problems x two non-reference algorithms
    // PMSM: ITLBO's five values all lie below TLBO's: U = 25 of 25, exact two-sided p = 2 / C(10, 5)
    // = 2/252 (by hand); Holm over two comparisons, both p = 2/252, gives 4/252 < 0.05; A12 = 1.
    EXPECT_EQ(tests.rows[0][tests.column("Rank-sum test")], "Wilcoxon rank-sum (Mann-Whitney U), exact");
    // Each algorithm's runs have their own seed: not paired, so the rank-sum test makes the marker.
    EXPECT_EQ(tests.rows[0][tests.column("Paired runs")], "no (seeds differ)");
    EXPECT_EQ(tests.rows[0][tests.column("Signed-rank p")], "");
    EXPECT_EQ(tests.rows[0][tests.column("Result by")], "rank-sum");
    EXPECT_NEAR(tests.number(0, tests.column("p")), 2.0 / 252.0, 1e-12);
    EXPECT_NEAR(tests.number(0, tests.column("p (Holm)")), 4.0 / 252.0, 1e-12);
    EXPECT_EQ(tests.number(0, tests.column("A12")), 1.0);
    EXPECT_EQ(tests.rows[0][tests.column("Result")], "-");
    const std::string latex = read_text(study_dir_ / "report" / "comparison.tex");
    EXPECT_NE(latex.find("\\toprule"), std::string::npos);
    // The method text is said once, in methods.tex; the note refers to it.
    EXPECT_NE(latex.find("(Methods)"), std::string::npos) << latex;
    const std::string methods = read_text(study_dir_ / "report" / "methods.tex");
    EXPECT_NE(methods.find("Holm"), std::string::npos);
    EXPECT_NE(methods.find("$\\alpha$ $=$ 0.05"), std::string::npos) << methods;
    EXPECT_NE(latex.find("{\\boldmath $"), std::string::npos) << latex; // the best median
    const CsvTable summary = read_csv(study_dir_ / "report" / "summary.csv");
    // Sphere, ITLBO: targets hit by runs 0, 1, 2 after 200, 300, 400; runs 3, 4 spent 1000 each:
    // ERT = (200 + 300 + 400 + 2000) / 3 (COCO's definition), success rate 3/5.
    EXPECT_NEAR(summary.number(3, summary.column("ERT")), 2900.0 / 3.0, 1e-9);
    EXPECT_EQ(summary.number(3, summary.column("Success rate")), 0.6);
    EXPECT_NE(read_text(study_dir_ / "report" / "across_problems.md").find("Friedman"), std::string::npos);
}

TEST(CriticalDifference, NemenyiByHand) {
    // Demsar (2006) Table 5(a): q_0.05 = 2.343 for k = 3, so with N = 22 problems
    // CD = 2.343 sqrt(3 * 4 / (6 * 22)) = 2.343 sqrt(1 / 11) = 0.70644 (by hand).
    const auto cd = nemenyi_critical_difference(3, 22, 0.05);
    ASSERT_TRUE(cd.has_value());
    EXPECT_NEAR(*cd, 2.343 / std::sqrt(11.0), 1e-12);
    // Table 5(b): q_0.10 = 1.645 for k = 2; N = 6: CD = 1.645 sqrt(2 * 3 / 36) = 1.645 / sqrt 6.
    EXPECT_NEAR(*nemenyi_critical_difference(2, 6, 0.10), 1.645 / std::sqrt(6.0), 1e-12);
    EXPECT_FALSE(nemenyi_critical_difference(3, 22, 0.01).has_value()); // not tabulated
    EXPECT_FALSE(nemenyi_critical_difference(11, 22, 0.05).has_value());
}

TEST_F(Report, CurveDataAverageOverRuns) {
    const CsvTable c = read_csv(study_dir_ / "report" / "curves_iteration.csv");
    // Row 2: PMSM, ITLBO, iteration 2 = the final values: mean 4.02, 5 runs.
    EXPECT_EQ(c.rows[2][c.column("iteration")], "2");
    EXPECT_EQ(c.number(2, c.column("runs")), 5.0);
    EXPECT_NEAR(c.number(2, c.column("mean")), 4.02, 1e-12);
    EXPECT_NEAR(c.number(0, c.column("mean")), 4 * 4.02, 1e-12); // iteration 0 holds 4 f
    const CsvTable p = read_csv(study_dir_ / "report" / "parameters_iteration.csv");
    EXPECT_EQ(p.rows[2][p.column("parameter")], "Rs");
    EXPECT_NEAR(p.number(2, p.column("mean")), 0.331, 1e-12);
    EXPECT_EQ(p.number(2, p.column("true")), 0.33);
}

TEST_F(Report, TargetHitsAreTheFirstRecordedEvaluationsWithinEachGap) {
    const CsvTable t = read_csv(study_dir_ / "report" / "target_hits.csv");
    // 2 problems x 3 algorithms x 5 runs x 11 targets.
    ASSERT_EQ(t.rows.size(), 330u);
    // PMSM, ITLBO run 0: final f = 4.0, f* = 3.9, recorded points (evaluations, f): checkpoints
    // (1, 32), (10, 16), (100, 8), curve (400, 16), (800, 8), (1200, 4), checkpoint (1200, 4).
    // Gap 1e2 is met at once (32 - 3.9 <= 100): evaluation 1; gap 10 first at 100 (8 - 3.9);
    // gap 1 at 1200; gap 0.1 never, since 4.0 - 3.9 is 0.10000000000000009 in doubles; gap 0.01 never.
    EXPECT_EQ(t.rows[0][t.column("evaluations")], "1");
    EXPECT_EQ(t.rows[1][t.column("evaluations")], "100");
    EXPECT_EQ(t.rows[2][t.column("evaluations")], "1200");
    EXPECT_EQ(t.rows[3][t.column("evaluations")], "");
    EXPECT_EQ(t.rows[4][t.column("evaluations")], "");
}

TEST_F(Report, OutputsMatchGoldenFiles) {
    const fs::path golden = fs::path(MHB_TEST_DATA_DIR) / "golden" / "report";
    const bool update = std::getenv("MHB_UPDATE_GOLDEN") != nullptr;
    std::size_t compared = 0;
    for (const auto& entry : fs::directory_iterator(study_dir_ / "report")) {
        const std::string name = entry.path().filename().string();
        // report.md, report.tex and index.html hold the (temporary) study path; html_report_test checks
        // the page, latex_golden_test a report.tex of a fixed path.
        if (name == "report.md" || name == "report.tex" || name == "index.html" || entry.is_directory())
            continue;
        if (update) {
            fs::create_directories(golden);
            fs::copy_file(entry.path(), golden / name, fs::copy_options::overwrite_existing);
        }
        ASSERT_TRUE(fs::exists(golden / name))
            << name << " has no golden copy (MHB_UPDATE_GOLDEN=1 makes it)";
        EXPECT_EQ(read_text(entry.path()), read_text(golden / name))
            << name << " differs from its golden copy";
        ++compared;
    }
    EXPECT_GE(compared, 25u);
}

TEST_F(Report, IohExportParsesBackWithTheRunsValues) {
    const fs::path folder = study_dir_ / "report" / "ioh" / "tlbo";
    // pmsm is function 200, its parameters a stable variant of it (see ioh_export.hpp).
    const fs::path dat =
        folder / "data_f200777259_pmsm_load_2_speed_2500" / "IOHprofiler_f200777259_DIM4.dat";
    std::ifstream in(dat);
    ASSERT_TRUE(in) << dat;
    std::vector<std::vector<std::pair<long, double>>> runs;
    std::string line;
    while (std::getline(in, line)) {
        if (line == "evaluations raw_y") {
            runs.emplace_back();
            continue;
        }
        ASSERT_FALSE(runs.empty()) << "data before the first header: " << line;
        std::istringstream fields(line);
        long evaluations = 0;
        double y = 0;
        ASSERT_TRUE(fields >> evaluations >> y) << line;
        runs.back().emplace_back(evaluations, y);
    }
    ASSERT_EQ(runs.size(), 5u); // five TLBO runs on the PMSM problem
    for (std::size_t i = 0; i < runs.size(); ++i) {
        ASSERT_FALSE(runs[i].empty());
        for (std::size_t k = 1; k < runs[i].size(); ++k) {
            EXPECT_GT(runs[i][k].first, runs[i][k - 1].first);   // evaluations increase
            EXPECT_LT(runs[i][k].second, runs[i][k - 1].second); // only improvements
        }
        // The last improvement is the run's final value, 5.0 + 0.2 i (see pmsm_run).
        EXPECT_DOUBLE_EQ(runs[i].back().second, 5.0 + 0.2 * static_cast<double>(i));
        EXPECT_EQ(runs[i].back().first, 600);
    }
    // The JSON parses (with Python's json module, where there is one) and lists the same runs.
    const fs::path json = folder / "IOHprofiler_f200777259_pmsm_load_2_speed_2500.json";
    ASSERT_TRUE(fs::exists(json));
    if (std::system("python3 -c 'import json' >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "no python3 to parse the JSON";
    const std::string check =
        "python3 -c \"import json,sys; d=json.load(open(sys.argv[1])); s=d['scenarios'][0]; "
        "assert d['algorithm']['name']=='tlbo' and d['function_id']==200777259 and not d['maximization']; "
        "assert s['dimension']==4 and "
        "s['path']=='data_f200777259_pmsm_load_2_speed_2500/IOHprofiler_f200777259_DIM4.dat'; "
        "assert [r['best']['y'] for r in s['runs']]==[5.0+0.2*i for i in range(5)], s['runs']; "
        "assert all(r['evals']==600 and len(r['best']['x'])==4 for r in s['runs'])\" '" +
        json.string() + "'";
    EXPECT_EQ(std::system(check.c_str()), 0) << check;
}

TEST_F(Report, LatexCompilesWhereATexEngineExists) {
    if (std::system("command -v pdflatex >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "no pdflatex on this machine";
    const fs::path dir = study_dir_ / "report";
    const std::string command = "cd '" + dir.string() +
                                "' && pdflatex -interaction=nonstopmode -halt-on-error " +
                                "report.tex >/dev/null 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << "see " << (dir / "report.log").string();
}

TEST(ReportFigures, SkippedWithOneClearLineWhenNoMatplotlib) {
    const fs::path dir = make_study("no_python");
    ReportOptions options;
    options.plot_script = fs::path(MHB_SOURCE_DIR) / "scripts" / "plot_study.py";
    options.python_candidates = {"/nonexistent/python3"};
    std::ostringstream console;
    build_report(load_study(dir), options, console);
    EXPECT_NE(console.str().find("figures skipped: no Python with matplotlib found; install matplotlib (apt "
                                 "install python3-matplotlib)"),
              std::string::npos)
        << console.str();
    EXPECT_TRUE(fs::exists(dir / "report" / "table2_fitness.md")); // the tables are still written
}

// Slow: matplotlib takes about 10 s to draw every figure.
TEST(SlowReportFigures, DrawnWhenMatplotlibIsThere) {
    ReportOptions options;
    if (!find_matplotlib_python(options.python_candidates))
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = make_study("figures");
    options.plot_script = fs::path(MHB_SOURCE_DIR) / "scripts" / "plot_study.py";
    std::ostringstream console;
    build_report(load_study(dir), options, console);
    const fs::path figures = dir / "report" / "figures";
    for (const char* name :
         {"convergence_iteration_all", "convergence_evaluations_all", // a panel per problem since issue 37
          "parameters_pmsm_load_2_speed_2500", // the four parameters in one figure since issue 37
          "final_values_all", "ecdf_target_all", "critical_difference", "ecdf_targets_all"})
        for (const char* ext : {".pdf", ".png"})
            EXPECT_GT(fs::file_size(figures / (std::string(name) + ext)), 1000u) << name << ext;
}

TEST(ReportOptionsCheck, BadOptionsAreClearErrors) {
    const fs::path dir = make_study("options");
    const StudyData study = load_study(dir);
    std::ostringstream console;
    ReportOptions options = no_figures();
    options.alpha = 1.5;
    EXPECT_THROW(build_report(study, options, console), std::invalid_argument);
    options = no_figures();
    options.formats = {"xls"};
    EXPECT_THROW(build_report(study, options, console), std::invalid_argument);
    options = no_figures();
    options.reference = "cmaes";
    try {
        build_report(study, options, console);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("the study has: itlbo, tlbo, pso"), std::string::npos)
            << e.what();
    }
    options.reference = "tlbo"; // a name that one algorithm has
    EXPECT_NO_THROW(build_report(study, options, console));
}

TEST(ReportInput, MissingOrTruncatedFilesAreClearErrors) {
    const fs::path dir = make_study("damaged");
    fs::remove(dir / "checkpoints.csv");
    try {
        (void)load_study(dir);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("checkpoints.csv"), std::string::npos) << e.what();
    }
    const fs::path truncated = make_study("truncated");
    const std::string runs = read_text(truncated / "runs.csv");
    std::ofstream(truncated / "runs.csv", std::ios::trunc) << runs.substr(0, runs.size() / 2);
    try {
        (void)load_study(truncated);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("runs.csv"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace mhb
