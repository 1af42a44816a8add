// The report for studies designed as a researcher designs them (issue 8), from StudyData built in
// memory: budgets reported separately, labels wherever an algorithm is named, pairing detected from
// seeds and the signed-rank test where runs are paired, the effects of an on/off factorial design,
// and the paper's published values only beside the configurations the paper ran.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>
#include <unistd.h>

#include "results/report/report.hpp"
#include "results/store/csv.hpp"
#include "results/store/study_index.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;
using mhb::test_support::read_text;

fs::path fresh_report_factors_dir(const std::string& name) {
    const fs::path dir = mhb::test_support::fresh_temporary_path("mhb_report_factors_", name);
    return dir;
}

RunRecord factors_run(const std::string& algorithm, const std::string& problem, const std::string& budget,
                      std::int64_t index, std::uint64_t seed, double f) {
    static std::int64_t id = 0;
    RunRecord r;
    r.run_id = id++;
    r.algorithm = algorithm;
    r.problem = problem;
    r.budget = budget;
    r.run_index = index;
    r.seed = seed;
    r.best_f = f;
    r.f_opt = 0.0;
    r.evaluations = 100;
    r.iterations = 2;
    r.best_x = {0.1, 0.2};
    r.curve = {{0, 50, 2 * f, {}}, {1, 100, f, {}}};
    r.checkpoints = {{1, 4 * f}, {100, f}};
    return r;
}

// Reference 1 + i; tlbo 1 + i + tlbo_d[i] (worse in 7 of 8 pairs); pso 1 + i + pso_e[i] (mixed); 8 runs each.
const std::vector<double> tlbo_d = {0.5, 0.25, -0.125, 0.75, 1.0, 0.375, 0.625, 0.875};
const std::vector<double> pso_e = {-0.5, 0.25, -0.125, 0.75, -1.0, 0.375, -0.625, 0.875};

StudyData paired_study(bool common_seeds, const std::string& budget = "iterations=2") {
    StudyData data;
    data.directory = "/nonexistent/paired";
    data.algorithms = {{"itlbo", "ITLBO (paper)", "itlbo:np=50,obl=on,stepwise=on,tutorial=on"},
                       {"tlbo", "TLBO", "tlbo:np=50"},
                       {"pso", "PSO", "pso:c1=2,c2=2,np=50,w=0.5"}};
    for (std::size_t a = 0; a < 3; ++a)
        for (std::int64_t i = 0; i < 8; ++i) {
            const double base = 1.0 + static_cast<double>(i);
            const double f = a == 0 ? base : base + (a == 1 ? tlbo_d : pso_e)[static_cast<std::size_t>(i)];
            const std::uint64_t seed = common_seeds ? 100 + static_cast<std::uint64_t>(i)
                                                    : 100 + 10 * a + static_cast<std::uint64_t>(i);
            data.runs.push_back(factors_run(data.algorithms[a].spec, "sphere:dim=2", budget, i, seed, f));
        }
    return data;
}

ReportOptions options_into(const fs::path& dir) {
    ReportOptions options;
    options.out_dir = dir;
    options.figures = false;
    return options;
}

std::size_t row_with_value(const CsvTable& t, const std::string& column, const std::string& value) {
    for (std::size_t r = 0; r < t.rows.size(); ++r)
        if (t.rows[r][t.column(column)] == value)
            return r;
    ADD_FAILURE() << value << " not in column " << column << " of " << t.path;
    return 0;
}

TEST(Pairing, DetectedFromTheSeedsOfEachRunIndex) {
    const StudyData common = paired_study(true);
    EXPECT_TRUE(StudyIndex(common).paired("sphere:dim=2"));
    EXPECT_FALSE(StudyIndex(paired_study(false)).paired("sphere:dim=2"));
    StudyData one_differs = common;
    one_differs.runs[20].seed += 1; // tlbo, run 4
    EXPECT_FALSE(StudyIndex(one_differs).paired("sphere:dim=2"));
    StudyData alone = common;
    alone.runs.resize(8); // only the reference: nothing to pair with
    EXPECT_FALSE(StudyIndex(alone).paired("sphere:dim=2"));
    // Pairs are formed on the run indices both completed.
    StudyData failed = common;
    failed.runs[9].ok = false; // tlbo, run 1
    const StudyIndex index(failed);
    EXPECT_TRUE(index.paired("sphere:dim=2"));
    const PairedValues pairs =
        paired_final_values(*index.find("sphere:dim=2", "tlbo"), *index.find("sphere:dim=2", "itlbo"));
    EXPECT_EQ(pairs.x.size(), 7u);
    EXPECT_EQ(pairs.y[1], 3.0); // run 2 of the reference
}

TEST(ReportPaired, SignedRankBesideRankSumAndMakesTheMarkers) {
    const fs::path dir = fresh_report_factors_dir("paired");
    std::ostringstream console;
    build_report(paired_study(true), options_into(dir), console);
    const CsvTable t = read_csv(dir / "tests.csv");
    const std::size_t tlbo = row_with_value(t, "Algorithm", "TLBO");
    // scipy.stats.wilcoxon(tlbo, itlbo, method='exact'): p = 0.015625 (V+ = 35); Holm over tlbo and
    // pso (p = 1.0): 0.03125 < 0.05, and V above its null mean 18: tlbo is worse.
    EXPECT_EQ(t.rows[tlbo][t.column("Paired runs")], "8");
    EXPECT_EQ(t.rows[tlbo][t.column("Signed-rank test")], "Wilcoxon signed-rank, exact");
    EXPECT_EQ(t.number(tlbo, t.column("V")), 35.0);
    EXPECT_DOUBLE_EQ(t.number(tlbo, t.column("Signed-rank p")), 0.015625);
    EXPECT_DOUBLE_EQ(t.number(tlbo, t.column("Signed-rank p (Holm)")), 0.03125);
    EXPECT_EQ(t.rows[tlbo][t.column("Result")], "-");
    EXPECT_EQ(t.rows[tlbo][t.column("Result by")], "signed-rank");
    // The rank-sum test alone sees overlapping samples and no difference.
    EXPECT_GT(t.number(tlbo, t.column("p (Holm)")), 0.5);
    const std::size_t pso = row_with_value(t, "Algorithm", "PSO");
    EXPECT_DOUBLE_EQ(t.number(pso, t.column("Signed-rank p")), 1.0); // V = 18 = n (n + 1) / 4
    EXPECT_EQ(t.rows[pso][t.column("Result")], "=");
    const std::string tests_md = read_text(dir / "tests.md");
    EXPECT_NE(tests_md.find("signed-rank test (all runs paired)"), std::string::npos) << tests_md;
    const CsvTable c = read_csv(dir / "comparison.csv");
    EXPECT_EQ(c.rows[0][c.column("Markers by")], "signed-rank (paired)");
    EXPECT_NE(c.rows[0][c.column("TLBO")].find(" -"), std::string::npos) << c.rows[0][c.column("TLBO")];
    EXPECT_NE(read_text(dir / "comparison.md").find("Wilcoxon signed-rank test of the paired differences"),
              std::string::npos);

    // The same values with per-algorithm seeds: unpaired, the rank-sum test makes the markers.
    const fs::path unpaired = fresh_report_factors_dir("unpaired");
    build_report(paired_study(false), options_into(unpaired), console);
    const CsvTable u = read_csv(unpaired / "tests.csv");
    const std::size_t row = row_with_value(u, "Algorithm", "TLBO");
    EXPECT_EQ(u.rows[row][u.column("Paired runs")], "no (seeds differ)");
    EXPECT_EQ(u.rows[row][u.column("Signed-rank p")], "");
    EXPECT_EQ(u.rows[row][u.column("Result")], "=");
    EXPECT_EQ(u.rows[row][u.column("Result by")], "rank-sum");
    EXPECT_NE(read_text(unpaired / "comparison.md").find("rank-sum test (Mann-Whitney U)"),
              std::string::npos);
}

TEST(ReportLabels, NameTheAlgorithmsInTablesAndCurveData) {
    const fs::path dir = fresh_report_factors_dir("labels");
    std::ostringstream console;
    build_report(paired_study(true), options_into(dir), console);
    const CsvTable summary = read_csv(dir / "summary.csv");
    EXPECT_EQ(summary.rows[0][summary.column("Algorithm")], "ITLBO (paper)");
    const CsvTable comparison = read_csv(dir / "comparison.csv");
    EXPECT_TRUE(comparison.has_column("ITLBO (paper) (reference)"));
    const CsvTable algorithms = read_csv(dir / "algorithms.csv");
    EXPECT_EQ(algorithms.rows[1][algorithms.column("Label")], "TLBO");
    EXPECT_EQ(algorithms.rows[1][algorithms.column("Full spec")], "tlbo:np=50");
    const CsvTable curves = read_csv(dir / "curves_iteration.csv");
    EXPECT_EQ(curves.rows[0][curves.column("algorithm")], "itlbo");
    EXPECT_EQ(curves.rows[0][curves.column("label")], "ITLBO (paper)");
    const CsvTable finals = read_csv(dir / "final_values.csv");
    EXPECT_EQ(finals.rows.back()[finals.column("label")], "PSO");
    // A label also names the reference.
    ReportOptions by_label = options_into(fresh_report_factors_dir("labels_reference"));
    by_label.reference = "TLBO";
    build_report(paired_study(true), by_label, console);
    EXPECT_NE(read_text(by_label.out_dir / "tests.md").find("### Tests against the reference TLBO"),
              std::string::npos);
}

TEST(ReportBudgets, EachBudgetInItsOwnFolderAndSaidInEveryTitle) {
    StudyData data = paired_study(true, "iterations=2");
    for (auto r : paired_study(true, "evaluations=500").runs) {
        r.run_id += 1000;
        r.best_f *= 10.0; // the larger budget's values differ, so the folders can be told apart
        data.runs.push_back(r);
    }
    const fs::path dir = fresh_report_factors_dir("budgets");
    std::ostringstream console;
    build_report(data, options_into(dir), console);
    const CsvTable budgets = read_csv(dir / "budgets.csv");
    ASSERT_EQ(budgets.rows.size(), 2u);
    EXPECT_EQ(budgets.rows[0][0], "iterations=2");
    EXPECT_EQ(budgets.rows[0][1], "iterations_2");
    EXPECT_EQ(budgets.rows[1][1], "evaluations_500");
    for (const auto& [slug, mean] :
         {std::pair<std::string, double>{"iterations_2", 4.5}, {"evaluations_500", 45.0}}) {
        const CsvTable s = read_csv(dir / slug / "summary.csv");
        ASSERT_EQ(s.rows.size(), 3u) << slug; // three algorithms, one budget
        EXPECT_DOUBLE_EQ(s.number(0, s.column("Mean")), mean) << slug;
        EXPECT_EQ(read_text(dir / slug / "budget.txt"),
                  budgets.rows[slug == "iterations_2" ? 0 : 1][0] + "\n");
        EXPECT_TRUE(fs::exists(dir / slug / "curves_iteration.csv"));
        EXPECT_TRUE(fs::exists(dir / slug / "tests.tex"));
    }
    EXPECT_NE(read_text(dir / "evaluations_500" / "summary.md").find("[budget evaluations=500]"),
              std::string::npos);
    EXPECT_NE(read_text(dir / "iterations_2" / "tests.md").find("Budget: iterations=2."), std::string::npos);
    const std::string report = read_text(dir / "report.md");
    EXPECT_NE(report.find("## Budget iterations=2 (iterations_2/)"), std::string::npos);
    EXPECT_NE(report.find("## Budget evaluations=500 (evaluations_500/)"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "summary.csv")); // nothing mixes the budgets
    // A reference that ran at one budget only is used there and replaced (and said) at the other.
    data.runs.erase(
        std::remove_if(data.runs.begin(), data.runs.end(),
                       [](const RunRecord& r) { return r.algorithm == "pso" && r.budget == "iterations=2"; }),
        data.runs.end());
    ReportOptions options = options_into(fresh_report_factors_dir("budgets_reference"));
    options.reference = "pso";
    std::ostringstream said;
    build_report(data, options, said);
    EXPECT_NE(said.str().find("budget iterations=2: --reference pso did not run at this budget"),
              std::string::npos)
        << said.str();
    // A study without several budgets keeps the flat layout.
    const fs::path flat = fresh_report_factors_dir("one_budget");
    build_report(paired_study(true), options_into(flat), console);
    EXPECT_TRUE(fs::exists(flat / "summary.csv"));
    EXPECT_FALSE(fs::exists(flat / "budgets.csv"));
}

// PMSM runs of the paper's ITLBO, two variants and TLBO with a non-default NP.
StudyData pmsm_variants_study() {
    StudyData data;
    data.directory = "/nonexistent/pmsm";
    data.study_text = "protocol = pmsm-paper\n"; // the paper's tables, at its budget (below)
    const std::vector<std::string> specs = {"itlbo", "itlbo:obl=off", "itlbo:label=mine", "tlbo:np=30"};
    std::int64_t id = 0;
    for (const auto& spec : specs)
        for (std::int64_t i = 0; i < 3; ++i) {
            RunRecord r = factors_run(spec, "pmsm:load=2,speed=2500", "iterations=150", i,
                                      7 + static_cast<std::uint64_t>(i), 4.0 + 0.1 * static_cast<double>(i));
            r.run_id = id++;
            r.f_opt = 3.9;
            r.parameter_names = {"Rs", "Ld", "Lq", "psi"};
            r.true_parameters = {0.330, 0.00324, 0.00324, 0.0776};
            r.best_x = r.true_parameters;
            r.x_opt = r.true_parameters;
            data.runs.push_back(r);
        }
    return data;
}

TEST(ReportPublished, OnlyBesideTheConfigurationsThePaperRan) {
    const fs::path dir = fresh_report_factors_dir("published");
    std::ostringstream console;
    build_report(pmsm_variants_study(), options_into(dir), console);
    const CsvTable t2 = read_csv(dir / "table2_fitness.csv");
    ASSERT_EQ(t2.rows.size(), 4u);
    EXPECT_EQ(t2.rows[0][t2.column("Algorithm")], "itlbo");
    EXPECT_EQ(t2.number(0, t2.column("Paper mean")), 3.9904);
    for (std::size_t r = 1; r < 4; ++r) {
        EXPECT_EQ(t2.rows[r][t2.column("Paper mean")], "") << t2.rows[r][0];
        EXPECT_EQ(t2.rows[r][t2.column("Paper std")], "") << t2.rows[r][0];
    }
    const CsvTable t3 = read_csv(dir / "table3_parameters.csv");
    std::size_t paper_rows = 0;
    for (const auto& row : t3.rows)
        if (row[1] == "paper identified") {
            ++paper_rows;
            EXPECT_EQ(row[0], "itlbo");
        }
    EXPECT_EQ(paper_rows, 1u);
    EXPECT_FALSE(fs::exists(dir / "table4_conditions.csv")); // one condition: no Table 4
    EXPECT_NE(read_text(dir / "table2_fitness.md").find("never beside a variant"), std::string::npos);
}

// The 2^2 design tutorial x obl on two problems with common seeds, at `budget`.
StudyData effects_study(const std::string& budget) {
    StudyData data;
    data.directory = "/nonexistent/ablation";
    const auto spec = [](bool tutorial, bool obl) {
        std::string params = std::string(tutorial ? "" : "tutorial=off");
        if (!obl)
            params = "obl=off" + std::string(params.empty() ? "" : ",") + params;
        return params.empty() ? std::string("itlbo") : "itlbo:" + params;
    };
    for (const bool tutorial : {true, false})
        for (const bool obl : {true, false})
            data.algorithms.push_back(
                {spec(tutorial, obl),
                 std::string("itlbo[T") + (tutorial ? "+" : "-") + "O" + (obl ? "+" : "-") + "]",
                 std::string("itlbo:np=50,obl=") + (obl ? "on" : "off") +
                     ",stepwise=on,tutorial=" + (tutorial ? "on" : "off")});
    for (const char* problem : {"sphere:dim=2", "rastrigin:dim=2"})
        for (const auto& a : data.algorithms)
            for (std::int64_t i = 0; i < 8; ++i) {
                const bool tutorial = a.full_spec.find("tutorial=on") != std::string::npos;
                const bool obl = a.full_spec.find("obl=on") != std::string::npos;
                // log10 f = -(3 + i / 8) [tutorial on] + (0.25 + i / 16) [obl on] - 1.
                const double di = static_cast<double>(i);
                const double y = -1.0 - (tutorial ? 3.0 + di / 8 : 0.0) + (obl ? 0.25 + di / 16 : 0.0);
                data.runs.push_back(factors_run(a.spec, problem, budget, i,
                                                50 + static_cast<std::uint64_t>(i), std::pow(10.0, y)));
            }
    return data;
}

// The design through the whole report.
TEST(ReportEffects, TableAndPlotDataForAFactorialDesign) {
    const StudyData data = effects_study("iterations=2");
    const fs::path dir = fresh_report_factors_dir("effects");
    std::ostringstream console;
    build_report(data, options_into(dir), console);
    EXPECT_NE(console.str().find("factorial design itlbo: obl x tutorial (2^2)"), std::string::npos)
        << console.str();
    const CsvTable t = read_csv(dir / "effects.csv");
    ASSERT_EQ(t.rows.size(), 9u); // 3 effects x (two problems + all problems)
    const auto find = [&](const std::string& problem, const std::string& effect) {
        for (std::size_t r = 0; r < t.rows.size(); ++r)
            if (t.rows[r][t.column("Problem")] == problem && t.rows[r][t.column("Effect")] == effect)
                return r;
        ADD_FAILURE() << problem << " " << effect;
        return std::size_t{0};
    };
    const std::size_t tutorial = find("sphere:dim=2", "tutorial");
    EXPECT_NEAR(t.number(tutorial, t.column("Mean")), -(3.0 + 3.5 / 8), 1e-9);
    EXPECT_EQ(t.rows[tutorial][t.column("Paired")], "yes");
    EXPECT_EQ(t.rows[tutorial][t.column("Blocks")], "8");
    // 8 distinct negative effects: exact p = 2/256; Holm over 3 effects: x3 (obl has the same p).
    EXPECT_DOUBLE_EQ(t.number(tutorial, t.column("p")), 2.0 / 256.0);
    EXPECT_DOUBLE_EQ(t.number(tutorial, t.column("p (Holm)")), 6.0 / 256.0);
    EXPECT_EQ(t.rows[tutorial][t.column("Reading")], "tutorial on lowers log10(f - f*) by 3.44: helps");
    EXPECT_EQ(
        t.rows[find("all problems (2)", "obl")][t.column("Reading")].rfind("obl on raises log10(f - f*)", 0),
        0u);
    EXPECT_EQ(t.rows[find("sphere:dim=2", "obl x tutorial")][t.column("Reading")], "no significant effect");
    EXPECT_NE(read_text(dir / "effects.md").find("[budget iterations=2]"), std::string::npos);
    const CsvTable means = read_csv(dir / "effect_means.csv");
    // Per analysis: 2 factors x 2 levels + 1 pair x 4 level pairs = 8 rows; 3 analyses.
    ASSERT_EQ(means.rows.size(), 24u);
    EXPECT_EQ(means.rows[0][means.column("factor")], "obl");
    EXPECT_EQ(means.rows[0][means.column("level")], "off");
    EXPECT_EQ(means.rows[4][means.column("factor2")], "tutorial");
}

// Slow: matplotlib draws every figure of two budgets.
TEST(SlowReportEffectsFigures, DrawnPerBudget) {
    ReportOptions options;
    if (!find_matplotlib_python(options.python_candidates))
        GTEST_SKIP() << "no Python with matplotlib";
    StudyData data = effects_study("iterations=2");
    for (auto r : effects_study("evaluations=300").runs) {
        r.best_f = r.best_f > 1e-3 ? r.best_f : 0.0; // at the optimum: log10 of the floor, finite
        data.runs.push_back(r);
    }
    options = options_into(fresh_report_factors_dir("effects_figures"));
    options.figures = true;
    options.plot_script = fs::path(MHB_SOURCE_DIR) / "scripts" / "plot_study.py";
    std::ostringstream console;
    build_report(data, options, console);
    for (const char* budget : {"iterations_2", "evaluations_300"})
        for (const char* name : {"effects_overview_itlbo", "effects_main_itlbo", "effects_interaction_itlbo",
                                 "convergence_evaluations_all"}) // two problems: a panel each (issue 37)
            for (const char* ext : {".pdf", ".png"}) {
                const fs::path figure = options.out_dir / budget / "figures" / (std::string(name) + ext);
                ASSERT_TRUE(fs::exists(figure)) << figure << "\n" << console.str();
                EXPECT_GT(fs::file_size(figure), 1000u) << figure;
                // Iterations are compared only where they end the runs (issue 37).
                EXPECT_EQ(fs::exists(options.out_dir / budget / "figures" / "convergence_iteration_all.png"),
                          std::string(budget) == "iterations_2");
            }
}

} // namespace
} // namespace mhb
