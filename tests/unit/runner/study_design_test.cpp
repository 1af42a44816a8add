// The design of a study as a researcher writes it: grids of variants with readable labels,
// canonical identity of specs, common random numbers across algorithms (ITLBO with its three
// switches off is TLBO, byte for byte, inside a study), budgets as a factor, study files with
// every error naming its file and line, and the cost estimate of --dry-run.
#include <gtest/gtest.h>
#include <set>

#include "problems/core/rng.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/calibration.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "runner/study/study_presets.hpp"
#include "tests/support/prepared_study.hpp"

namespace mhb {
namespace {

std::vector<std::string> error_lines(const Study& s) {
    try {
        (void)prepare_study(s);
    } catch (const std::invalid_argument& e) {
        std::vector<std::string> out;
        std::string text = e.what();
        for (std::size_t start = 0; start < text.size();) {
            const auto end = std::min(text.find('\n', start), text.size());
            out.push_back(text.substr(start, end - start));
            start = end + 1;
        }
        return out;
    }
    return {};
}

Study paper_study(std::vector<std::string> algorithms, std::int64_t runs = 3) {
    Study s;
    s.algorithms = std::move(algorithms);
    s.problems = {"pmsm:speed=2500,load=2", "rastrigin:dim=5,shift=on,instance=2"};
    s.runs = runs;
    s.seed = 11;
    s.budgets.front().max_iterations = 12;
    return s;
}

TEST(StudyDesign, AGridIsEightLabelledVariantsInAFixedOrder) {
    const PreparedStudy p =
        prepare_study(paper_study({"itlbo:tutorial={on,off},stepwise={on,off},obl={on,off}"}));
    ASSERT_EQ(p.algorithms.size(), 8u);
    std::vector<std::string> labels;
    for (const auto& a : p.algorithms)
        labels.push_back(a.info.label);
    EXPECT_EQ(labels,
              (std::vector<std::string>{"itlbo[T+S+O+]", "itlbo[T+S+O-]", "itlbo[T+S-O+]", "itlbo[T+S-O-]",
                                        "itlbo[T-S+O+]", "itlbo[T-S+O-]", "itlbo[T-S-O+]", "itlbo[T-S-O-]"}));
    EXPECT_EQ(p.algorithms.front().info.spec, "itlbo"); // the paper's configuration: every default
    EXPECT_EQ(p.algorithms.back().info.spec, "itlbo:obl=off,stepwise=off,tutorial=off");
    EXPECT_NE(p.algorithms.back().info.full_spec.find("np=50"), std::string::npos);
    // A study file keeps each variant with its label, and reads back to the same study.
    const std::string text = study_ini(p.study);
    EXPECT_NE(text.find("algorithms = itlbo:obl=off,label=itlbo[T+S+O-]\n"), std::string::npos) << text;
    EXPECT_EQ(study_ini(prepare_study(parse_study_ini(text, "study.ini")).study), text);

    const PreparedStudy w =
        prepare_study(paper_study({"pso:w={0.4,0.5,0.7}", "de:F={0.5,0.9},CR={0.1,0.9}"}));
    std::vector<std::string> more;
    for (const auto& a : w.algorithms)
        more.push_back(a.info.label);
    EXPECT_EQ(more, (std::vector<std::string>{"pso[w=0.4]", "pso[w=0.5]", "pso[w=0.7]", "de[F=0.5,CR=0.1]",
                                              "de[F=0.5,CR=0.9]", "de[F=0.9,CR=0.1]", "de[F=0.9,CR=0.9]"}));
    // Switches that share a first letter are named in full.
    const PreparedStudy o = prepare_study(paper_study({"itlbo:obl={on,off},obl_greedy={on,off}"}));
    EXPECT_EQ(o.algorithms[1].info.label, "itlbo[obl+,obl_greedy-]");
}

TEST(StudyDesign, LabelsNameVariantsAndSameMeaningSpecsAreOneOptimiser) {
    const PreparedStudy p = prepare_study(paper_study({"tlbo:label=TLBO (Rao 2011)", "pso:w=0.7"}));
    EXPECT_EQ(p.algorithms[0].info.label, "TLBO (Rao 2011)");
    EXPECT_EQ(p.algorithms[0].info.spec, "tlbo");
    EXPECT_EQ(p.algorithms[1].info.label, "PSO (w=0.7)");
    EXPECT_EQ(error_lines(paper_study({"tlbo", "tlbo:np=50"})),
              (std::vector<std::string>{
                  "algorithm 'tlbo:np=50' is the same optimiser as 'tlbo' (both are 'tlbo')"}));
    EXPECT_EQ(error_lines(paper_study({"tlbo:label=x", "pso:label=x"})),
              (std::vector<std::string>{"algorithm label 'x' names both 'tlbo' and 'pso'"}));
    EXPECT_EQ(
        error_lines(paper_study({"pso:w={0.4,0.5},label=p"})),
        (std::vector<std::string>{"pso: label 'p' would name all 2 variants of the grid; leave it out (each "
                                  "variant gets a label of its own) or write the variants one by one"}));
    // The grid and the plain specs of the same variant are recognised as one.
    EXPECT_EQ(error_lines(paper_study({"itlbo:obl={on,off}", "itlbo:obl=false"})).size(), 1u);
    Study q = paper_study({"tlbo"});
    q.problems = {"sphere:dim=10", "sphere:dim=1e1"};
    EXPECT_EQ(error_lines(q),
              (std::vector<std::string>{"problem 'sphere:dim=10' is the same problem as 'sphere:dim=10'"}));
}

// Without label=, an algorithm is named by the short display name its registration declares, with
// its non-default parameters; study.ini keeps the canonical spec (the label is derived again).
TEST(StudyDesign, DefaultLabelsAreTheRegisteredDisplayNamesWithTheirNonDefaultParameters) {
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"itlbo", "ITLBO"},
        {"tlbo", "TLBO"},
        {"pso", "PSO"},
        {"de", "DE"},
        {"lshade", "L-SHADE"},
        {"jso", "jSO"},
        {"nl-shade-lbc", "NL-SHADE-LBC"},
        {"lshade-cnepsin", "LSHADE-cnEpSin"},
        {"cmaes", "CMA-ES (IPOP)"},
        {"cmaes:restarts=bipop,lambda=20", "CMA-ES (BIPOP, lambda=20)"},
        {"nlopt:algorithm=LN_BOBYQA", "BOBYQA"},
        {"nlopt:algorithm=LN_NELDERMEAD", "Nelder-Mead"},
        {"nlopt:algorithm=GN_MLSL,local=LN_SBPLX", "MLSL (local=LN_SBPLX)"},
        {"pso:w=0.50", "PSO"}, // a default written out is no variant
        {"tlbo:np=30", "TLBO (np=30)"}};
    std::vector<std::string> specs;
    std::vector<std::string> labels;
    for (const auto& [spec, label] : expected)
        if (spec != "pso:w=0.50") {
            specs.push_back(spec);
            labels.push_back(label);
        }
    const PreparedStudy p = prepare_study(paper_study(specs));
    ASSERT_EQ(p.algorithms.size(), specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i)
        EXPECT_EQ(p.algorithms[i].info.label, labels[i]) << specs[i];
    EXPECT_EQ(prepare_study(paper_study({"pso:w=0.50"})).algorithms[0].info.label, "PSO");
    EXPECT_EQ(study_ini(p.study).find("label="), std::string::npos) << study_ini(p.study);
    // Grid variants keep their grid labels.
    EXPECT_EQ(prepare_study(paper_study({"itlbo:obl={on,off}"})).algorithms[1].info.label, "itlbo[O-]");
}

// A short label two specs would share, or one that another spec's label= takes, falls back to the
// canonical spec, whatever the order; the duplicate-label check still holds for given labels.
TEST(StudyDesign, DefaultLabelsThatWouldClashFallBackToTheCanonicalSpec) {
    for (const auto& order : {std::vector<std::string>{"cmaes", "tlbo:label=CMA-ES (IPOP)"},
                              std::vector<std::string>{"tlbo:label=CMA-ES (IPOP)", "cmaes"}}) {
        const PreparedStudy p = prepare_study(paper_study(order));
        std::set<std::string> labels;
        for (const auto& a : p.algorithms)
            labels.insert(a.info.label);
        EXPECT_EQ(labels, (std::set<std::string>{"CMA-ES (IPOP)", "cmaes"}));
    }
    EXPECT_EQ(error_lines(paper_study({"tlbo:label=x", "pso:label=x"})).size(), 1u);
}

TEST(StudyDesign, CommonRandomNumbersMakeItlboWithSwitchesOffTlboInsideAStudy) {
    for (const char* r : {"coordinate", "learner"}) {
        const std::string suffix = std::string(",r=") + r;
        const PreparedStudy p = prepare_study(paper_study(
            {"itlbo:tutorial=off,stepwise=off,obl=off" + suffix, "tlbo:r=" + std::string(r), "pso"}));
        const auto a = static_cast<std::int64_t>(p.algorithms.size());
        for (std::int64_t pr = 0; pr < 2; ++pr)
            for (std::int64_t run = 0; run < p.study.runs; ++run) {
                const RunRecord itlbo = execute_run(p.request((pr * a + 0) * p.study.runs + run));
                const RunRecord tlbo = execute_run(p.request((pr * a + 1) * p.study.runs + run));
                const RunRecord pso = execute_run(p.request((pr * a + 2) * p.study.runs + run));
                ASSERT_TRUE(itlbo.ok && tlbo.ok && pso.ok);
                EXPECT_EQ(itlbo.seed, tlbo.seed);
                EXPECT_EQ(itlbo.seed, pso.seed);
                EXPECT_EQ(itlbo.best_f, tlbo.best_f) << r;
                EXPECT_EQ(itlbo.best_x, tlbo.best_x);
                EXPECT_EQ(itlbo.evaluations, tlbo.evaluations);
                ASSERT_EQ(itlbo.curve.size(), tlbo.curve.size());
                for (std::size_t i = 0; i < itlbo.curve.size(); ++i) {
                    EXPECT_EQ(itlbo.curve[i].best_f, tlbo.curve[i].best_f);
                    EXPECT_EQ(itlbo.curve[i].best_x, tlbo.curve[i].best_x);
                }
                // Same NP, same uniform initialisation: PSO starts from the same population, so
                // the best point after initialisation (iteration 0) is the same for all three.
                EXPECT_EQ(pso.curve.front().evaluations, tlbo.curve.front().evaluations);
                EXPECT_EQ(pso.curve.front().best_f, tlbo.curve.front().best_f);
                EXPECT_EQ(pso.curve.front().best_x, tlbo.curve.front().best_x);
            }
    }
}

TEST(StudyDesign, PerAlgorithmSeedsAreTheOldDerivation) {
    Study s = paper_study({"tlbo", "itlbo:tutorial=off,stepwise=off,obl=off"});
    s.seeds = SeedMode::per_algorithm;
    const PreparedStudy p = prepare_study(s);
    const RunRequest tlbo = p.request(0);
    const RunRequest itlbo = p.request(p.study.runs);
    EXPECT_EQ(tlbo.seed, derive_seed(11, "tlbo", p.problems[0].spec, 0));
    EXPECT_NE(tlbo.seed, itlbo.seed);
    EXPECT_NE(execute_run(tlbo).best_f, execute_run(itlbo).best_f);
    EXPECT_NE(study_ini(p.study).find("seeds = per-algorithm\n"), std::string::npos);
}

TEST(StudyDesign, BudgetsAreAFactorWithTheSameSeedsUnderEach) {
    Study s = paper_study({"tlbo", "pso"}, 2);
    s.budgets = {parse_budget("iterations=10"), parse_budget("evaluations=1e3,target=1e-8")};
    const PreparedStudy p = prepare_study(s);
    EXPECT_EQ(p.budget_texts, (std::vector<std::string>{"iterations=10", "evaluations=1000,target=1e-08"}));
    ASSERT_EQ(p.run_count(), 2 * 2 * 2 * 2);
    const std::int64_t per_budget = p.run_count() / 2;
    for (std::int64_t id = 0; id < per_budget; ++id) {
        const RunRequest first = p.request(id);
        const RunRequest second = p.request(id + per_budget);
        EXPECT_EQ(first.budget_text, "iterations=10");
        EXPECT_EQ(second.budget_text, "evaluations=1000,target=1e-08");
        EXPECT_EQ(first.seed, second.seed); // paired across budgets too
        EXPECT_EQ(first.algorithm_spec, second.algorithm_spec);
        EXPECT_EQ(execute_run(second).budget, "evaluations=1000,target=1e-08");
    }
    s.budgets.push_back(parse_budget("evaluations=1000,target=1e-8"));
    EXPECT_EQ(error_lines(s),
              (std::vector<std::string>{"budget 'evaluations=1000,target=1e-08' is listed twice"}));
    EXPECT_THROW((void)parse_budget("target=1"), std::invalid_argument);
    EXPECT_THROW((void)parse_budget("iterations=0"), std::invalid_argument);
    EXPECT_THROW((void)parse_budget("iterations=5,speed=2"), std::invalid_argument);
}

TEST(StudyFileDesign, AcceptsTheCommandLinesNamesGridsContinuationsAndABom) {
    const Study s = parse_study_ini("\xEF\xBB\xBF# summary line\n"
                                    "algorithms = itlbo:tutorial={on, off} \\\n"
                                    "             tlbo   # the reference\n"
                                    "algorithm = pso\n"
                                    "problems = sphere:dim=2\n"
                                    "    sphere:dim=3\n"
                                    "seeds = per-algorithm\n"
                                    "budget = iterations=5\n"
                                    "budgets = evaluations=100\n"
                                    "target = 1e-3\n",
                                    "f.ini");
    EXPECT_EQ(s.algorithms, (std::vector<std::string>{"itlbo:tutorial={on,off}", "tlbo", "pso"}));
    EXPECT_EQ(s.algorithm_origins, (std::vector<std::string>{"f.ini:2", "f.ini:2", "f.ini:4"}));
    EXPECT_EQ(s.problems, (std::vector<std::string>{"sphere:dim=2", "sphere:dim=3"}));
    EXPECT_EQ(s.seeds, SeedMode::per_algorithm);
    ASSERT_EQ(s.budgets.size(), 2u);
    EXPECT_EQ(budget_text(s.budgets[0]), "iterations=5,target=0.001");
    EXPECT_EQ(budget_text(s.budgets[1]), "evaluations=100,target=0.001");
    EXPECT_EQ(study_file_summary("# summary line\nruns = 1\n"), "summary line");
}

TEST(StudyFileDesign, EveryErrorOfAFileIsReportedWithItsLine) {
    Study s;
    std::vector<std::string> errors;
    parse_study_file("runs = 0x10\n"
                     "[study]\n"
                     "just words\n"
                     "colour = blue\n"
                     "out = /tmp/x\n"
                     "seeds = sometimes\n"
                     "iterations = 1e300\n"
                     "runs = 3\n"
                     "budget = iterations=-1\n"
                     "algorithms = pso:w=1.5 tlbo:np=1\n"
                     "problems = sphere:dim={2,2}\n",
                     "bad.ini", s, errors);
    const std::string known_keys =
        "algorithms, algorithm, problems, problem, runs, precision, max-runs, initial-runs, round-runs, "
        "seed, seeds, iterations, "
        "evaluations, budget, budgets, target, relative-target, protocol, plugins, "
        "plugin";
    EXPECT_EQ(errors,
              (std::vector<std::string>{
                  "bad.ini:1: runs = 0x10 is not an integer",
                  "bad.ini:2: sections ('[study]') are not used in study files",
                  "bad.ini:3: 'just words' is not key = value",
                  "bad.ini:4: unknown key 'colour'; known: " + known_keys,
                  "bad.ini:5: unknown key 'out' (it is not part of a study: give --out on the command line)",
                  "bad.ini:6: seeds = sometimes is not one of {common, per-algorithm}",
                  "bad.ini:7: iterations = 1e300 is too large (at most 1000000000000000)",
                  "bad.ini:8: 'runs' is given twice",
                  "bad.ini:9: budget: parameter 'iterations' = -1 is outside [1, 1000000000000000]",
              }));
    // The specs' own errors come from prepare_study, each with the line it was written on.
    EXPECT_EQ(error_lines(s), (std::vector<std::string>{
                                  "bad.ini:10: pso: parameter 'w' = 1.5 is outside [0, 1]",
                                  "bad.ini:10: tlbo: parameter 'np' = 1 is outside [2, 100000]",
                                  "bad.ini:11: problem 'sphere:dim={2,2}': parameter 'dim': value '2' is "
                                  "listed twice in the set",
                                  "budget: give a number of iterations or of evaluations (or both)"}));
}

TEST(StudyDesign, ShippedPresetsAreStudyFilesAndTheAblationIsTheFullFactorial) {
    const StudyPreset& ablation = find_study_preset("ablation");
    EXPECT_EQ(ablation.origin, "scripts/studies/ablation.ini");
    const PreparedStudy p = prepare_study(ablation.study);
    EXPECT_EQ(p.algorithms.size(), 8u);
    EXPECT_EQ(p.problems.size(), 3u);
    EXPECT_EQ(p.budget_texts, (std::vector<std::string>{"iterations=150", "evaluations=15050"}));
    EXPECT_EQ(p.study.runs, 20);
    EXPECT_EQ(p.study.seeds, SeedMode::common);
    const PreparedStudy bbob = prepare_study(find_study_preset("bbob").study);
    EXPECT_EQ(bbob.problems.size(), 24u * 5u * 15u);
    EXPECT_EQ(bbob.problems.back().spec, "bbob:dim=20,f=24,instance=15");
    for (const char* name : {"fair", "paper", "paper-table4", "centre-bias", "smoke"})
        EXPECT_NO_THROW((void)prepare_study(find_study_preset(name).study)) << name;
}

// Issue 38's timing preset: COCO's timing experiment, every cheap optimiser on the sphere at
// D = 2 ... 100, one evaluation budget for all.
TEST(StudyDesign, TheTimingPresetTimesTheSphereAtCocosDimensions) {
    const PreparedStudy timing = prepare_study(find_study_preset("timing").study);
    EXPECT_EQ(test_support::problem_specs(timing),
              (std::vector<std::string>{"sphere:dim=2", "sphere:dim=3", "sphere:dim=5", "sphere:dim=10",
                                        "sphere:dim=20", "sphere:dim=40", "sphere:dim=100"}));
    EXPECT_EQ(timing.algorithms.size(), 11u);
    EXPECT_EQ(timing.algorithms.front().info.spec, "random-search"); // the floor, first
    EXPECT_EQ(timing.budget_texts, (std::vector<std::string>{"evaluations=200000"}));
}

// Issue 35's presets: the flux map against every optimiser at two budgets, and the ladder of three
// identification problems, each with a known, non-zero f* for the relative target (1e-6 |f*|).
TEST(StudyDesign, TheFluxMapAndLadderPresetsMeasureSuccessRelativeToFStar) {
    const PreparedStudy flux = prepare_study(find_study_preset("flux-map").study);
    EXPECT_EQ(test_support::problem_specs(flux), (std::vector<std::string>{"fluxmap:model=pmsyrm"}));
    EXPECT_EQ(flux.budget_texts, (std::vector<std::string>{"evaluations=20000,relative_target=1e-06",
                                                           "evaluations=200000,relative_target=1e-06"}));
    EXPECT_EQ(flux.algorithms.size(), 19u);
    std::set<std::string> labels;
    for (const auto& a : flux.algorithms)
        labels.insert(a.info.label);
    for (const char* label :
         {"ITLBO", "itlbo[T+S-O-]", "itlbo[T-S+O-]", "itlbo[T-S-O+]", "TLBO", "bipop-cmaes", "bobyqa",
          "sbplx", "nelder-mead", "crs2-lm", "direct-l", "isres", "esch"})
        EXPECT_EQ(labels.count(label), 1u) << label;
    // A run on the flux map stops once f - f* <= 1e-6 x f* (36.0995588759095 A^2, the shipped one).
    const double f_star = flux.problems.front().problem->known_optimum()->f;
    EXPECT_NEAR(f_star, 36.0995588759095, 1e-12);
    EXPECT_EQ(flux.request(0).budget.target_error, 1e-6 * f_star);

    const PreparedStudy ladder = prepare_study(find_study_preset("pmsm-ladder").study);
    ASSERT_EQ(ladder.problems.size(), 3u);
    EXPECT_EQ(ladder.algorithms.size(), 9u);
    for (const auto& problem : ladder.problems) {
        const auto optimum = problem.problem->known_optimum();
        ASSERT_TRUE(optimum.has_value());
        EXPECT_GT(optimum->f, 0.0); // noisy data: the relative target means something
    }
    for (const auto* p : {&flux, &ladder}) {
        EXPECT_EQ(p->study.runs, 20);
        EXPECT_EQ(p->study.seeds, SeedMode::common);
    }
}

TEST(StudyDesign, TheEstimateCountsEvaluationBudgetsExactly) {
    Study s = paper_study({"tlbo", "pso", "itlbo"}, 4);
    s.budgets = {parse_budget("evaluations=700"), parse_budget("iterations=5")};
    const PreparedStudy p = prepare_study(s);
    const StudyEstimate e = estimate_study(p);
    ASSERT_EQ(e.budgets.size(), 2u);
    EXPECT_TRUE(e.budgets[0].exact);
    EXPECT_EQ(e.budgets[0].evaluations, 700.0 * 3 * 2 * 4);
    EXPECT_FALSE(e.budgets[1].exact);
    // TLBO: NP + 5 * 2 NP; PSO: NP + 5 NP; ITLBO about NP + 5 NP (D + 1.1) on D = 4 and D = 5.
    EXPECT_GT(e.budgets[1].evaluations, (550.0 + 300.0 + 50.0 + 5 * 50 * 5) * 2 * 4 * 0.9);
    EXPECT_GT(e.cpu_seconds(), 0.0);
    EXPECT_EQ(e.calibration_runs, 2 * 3 * 2);
}

// A calibration run is its run with the budget cut to a fiftieth, never below 2000 evaluations or
// 3 iterations, never above the budget itself, and without the target.
TEST(StudyDesign, ACalibrationRunIsItsRunWithTheBudgetCutToAFiftieth) {
    Study s = paper_study({"pso"}, 1);
    s.problems = {"sphere:dim=3"};
    s.budgets = {parse_budget("evaluations=1000000,target=1e-300"), parse_budget("evaluations=5000"),
                 parse_budget("evaluations=1500"), parse_budget("iterations=600"),
                 parse_budget("iterations=100")};
    const PreparedStudy p = prepare_study(s);
    const auto calibrated = [&](std::size_t budget) {
        return calibration_run(p.request(static_cast<std::int64_t>(budget)));
    };
    EXPECT_EQ(calibrated(0).evaluations, 20000); // the target is dropped: the sphere reaches 1e-300 never
    EXPECT_EQ(calibrated(1).evaluations, 2000);
    EXPECT_EQ(calibrated(2).evaluations, 1500);
    EXPECT_EQ(calibrated(3).iterations, 12);
    EXPECT_EQ(calibrated(4).iterations, 3);
}

// Two problems of each dimension are calibrated (first and last of that dimension), whatever the
// order of the list, and each algorithm's share of the time is reported.
TEST(StudyDesign, TheEstimateCalibratesTwoProblemsOfEachDimension) {
    Study s = paper_study({"pso", "tlbo"}, 2);
    s.problems = {"sphere:dim=2",    "rastrigin:dim=6", "sphere:dim=6",
                  "ellipsoid:dim=2", "rastrigin:dim=2", "ackley:dim=6"};
    s.budgets = {parse_budget("evaluations=400")};
    const PreparedStudy p = prepare_study(s);
    const StudyEstimate e = estimate_study(p, 2);
    EXPECT_EQ(e.calibration_runs, 2 * 2 * 2); // algorithms x dimensions x 2
    ASSERT_EQ(e.algorithm_seconds.size(), 2u);
    EXPECT_GT(e.algorithm_seconds[0], 0.0);
    EXPECT_GT(e.algorithm_seconds[1], 0.0);
    EXPECT_DOUBLE_EQ(e.algorithm_seconds[0] + e.algorithm_seconds[1], e.cpu_seconds());
    EXPECT_EQ(e.budgets[0].evaluations, 400.0 * 6 * 2 * 2);
}

} // namespace
} // namespace mhb
