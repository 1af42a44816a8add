// Budgets that depend on the problem's dimension (`evaluations=10000*dim`,
// `evaluations=dim10:200000+dim20:1000000`), targets relative to the problem's f*
// (`relative_target=1e-6`) and the `protocol` key of a study: parsing and its errors, each run
// getting the count of its own dimension and the target of its own f*, every configuration error
// named before a run starts, study.ini round trips, the dry run's count, and run identities of
// existing studies unchanged (pinned to the store an earlier mhbench wrote).
#include <gtest/gtest.h>
#include <stdexcept>

#include "runner/distribution/shards.hpp"
#include "runner/execution/run_identity.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/calibration.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "runner/study/study_options.hpp"
#include "tests/unit/runner/test_problem.hpp"

namespace mhb {
namespace {

std::string error_of(const Study& study) {
    try {
        (void)prepare_study(study);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "no error";
}

Study sphere_study(const std::string& budget) {
    Study s;
    s.algorithms = {"random-search", "pso"};
    s.problems = {"sphere:dim={2,5}"};
    s.runs = 3;
    s.budgets = {parse_budget(budget)};
    return s;
}

TEST(StudyBudget, EvaluationsByDimensionReadAndWriteBack) {
    const StudyBudget per = parse_budget("evaluations=1e4*dim,target=1e-8");
    EXPECT_FALSE(per.max_evaluations);
    ASSERT_TRUE(per.evaluations_by_dimension);
    EXPECT_EQ(budget_text(per), "evaluations=10000*dim,target=1e-08");
    EXPECT_EQ(per.for_problem(10, std::nullopt).max_evaluations, 100000);
    EXPECT_EQ(per.for_problem(30, std::nullopt).max_evaluations, 300000);
    EXPECT_EQ(per.for_problem(30, std::nullopt).target_error, 1e-8);

    const StudyBudget listed = parse_budget("iterations=50,evaluations=dim20:1000000+dim10:200000");
    EXPECT_EQ(budget_text(listed), "iterations=50,evaluations=dim10:200000+dim20:1000000");
    EXPECT_EQ(listed.for_problem(20, std::nullopt).max_evaluations, 1000000);
    EXPECT_EQ(listed.for_problem(20, std::nullopt).max_iterations, 50);
    try {
        (void)listed.for_problem(30, std::nullopt);
        ADD_FAILURE() << "dimension 30 is not listed";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "budget 'iterations=50,evaluations=dim10:200000+dim20:1000000' gives no "
                               "evaluations at dimension 30; it lists 10, 20");
    }
    // Plain budgets are what they were, text and messages alike.
    EXPECT_EQ(budget_text(parse_budget("evaluations=1e5")), "evaluations=100000");
    EXPECT_EQ(budget_text(parse_budget("evaluations=1e+5")), "evaluations=100000");
    EXPECT_EQ(parse_budget("evaluations=15050").for_problem(7, std::nullopt).max_evaluations, 15050);
    try {
        (void)parse_budget("evaluations=abc");
        ADD_FAILURE();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "budget: parameter 'evaluations' = abc is not an integer");
    }
    EXPECT_THROW((void)parse_budget("evaluations=100*D"), std::invalid_argument);
}

TEST(StudyBudget, EachRunGetsTheCountOfItsDimension) {
    const PreparedStudy p = prepare_study(sphere_study("evaluations=100*dim"));
    EXPECT_EQ(p.budget_texts, (std::vector<std::string>{"evaluations=100*dim"}));
    ASSERT_EQ(p.run_count(), 12);
    for (std::int64_t id = 0; id < p.run_count(); ++id) {
        const RunRequest request = p.request(id);
        const std::int64_t dimension = p.problems[p.cell(id).problem].problem->dimension();
        EXPECT_EQ(request.budget.max_evaluations, 100 * dimension);
        EXPECT_EQ(request.budget_text, "evaluations=100*dim"); // one budget: one report for all dimensions
    }
    const RunRecord record = execute_run(p.request(p.run_count() - 1)); // pso on sphere:dim=5
    EXPECT_EQ(record.evaluations, 500);
    EXPECT_EQ(record.budget, "evaluations=100*dim");
    // The identity names the rule, not the count.
    EXPECT_NE(run_key(p, 0).facts.find("budget = evaluations=100*dim\n"), std::string::npos);
    // The dry run's count is exact: (200 + 500) x 2 algorithms x 3 runs.
    const StudyEstimate estimate = estimate_study(p);
    EXPECT_TRUE(estimate.budgets[0].exact);
    EXPECT_EQ(estimate.budgets[0].evaluations, 4200.0);
    // Shards weigh each run by its own count x its dimension.
    const std::vector<double> costs = estimated_run_costs(p);
    EXPECT_EQ(costs.front(), 200.0 * 2);
    EXPECT_EQ(costs.back(), 500.0 * 5);
}

TEST(StudyBudget, AListMustNameEveryDimensionOfTheStudy) {
    Study s = sphere_study("evaluations=dim2:100");
    s.problems = {"sphere:dim={2,3,5}", "rastrigin:dim=5"};
    EXPECT_EQ(error_of(s), "budget 'evaluations=dim2:100' gives no evaluations at dimension 3 (problem "
                           "'sphere:dim=3'); it lists 2\n"
                           "budget 'evaluations=dim2:100' gives no evaluations at dimension 5 (problem "
                           "'sphere:dim=5' and 1 more); it lists 2");
}

TEST(StudyBudget, StudyFilesAndTheCommandLineTakeIt) {
    const Study s =
        parse_study_ini("algorithms = pso\nproblems = sphere:dim={2,5}\nruns = 2\n"
                        "budget = evaluations=50*dim\nbudget = iterations=3,evaluations=dim2:40+dim5:90\n",
                        "b.ini");
    ASSERT_EQ(s.budgets.size(), 2u);
    EXPECT_EQ(budget_text(s.budgets[0]), "evaluations=50*dim");
    EXPECT_EQ(budget_text(s.budgets[1]), "iterations=3,evaluations=dim2:40+dim5:90");
    const PreparedStudy p = prepare_study(s);
    const std::string text = study_ini(p.study);
    EXPECT_NE(text.find("budget = evaluations=50*dim\nbudget = iterations=3,evaluations=dim2:40+dim5:90\n"),
              std::string::npos)
        << text;
    EXPECT_EQ(study_ini(prepare_study(parse_study_ini(text, "study.ini")).study), text);
    EXPECT_EQ(text.find("protocol"), std::string::npos); // no protocol: no line

    // `evaluations = ...` (the command line's --evaluations) takes the same forms.
    Study cli;
    std::vector<std::string> errors;
    StudyOptionReader reader(cli);
    reader.apply("evaluations", "1000*dim", "", errors);
    reader.finish(errors);
    EXPECT_TRUE(errors.empty());
    ASSERT_EQ(cli.budgets.size(), 1u);
    EXPECT_EQ(budget_text(cli.budgets[0]), "evaluations=1000*dim");

    Study bad;
    parse_study_file("evaluations = 1000*D\nbudget = evaluations=dim10:5+dim10:6\n", "bad.ini", bad, errors);
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_EQ(errors[0].rfind("bad.ini:1: budget: parameter 'evaluations' = 1000*D multiplies by 'D', not by "
                              "dim; write ",
                              0),
              0u)
        << errors[0];
    EXPECT_EQ(
        errors[1].rfind("bad.ini:2: budget: parameter 'evaluations' = dim10:5+dim10:6 lists dimension 10 "
                        "twice; write ",
                        0),
        0u)
        << errors[1];
}

TEST(StudyBudget, RelativeTargetReadWrittenBackAndResolvedAgainstTheProblemsOptimum) {
    const StudyBudget b = parse_budget("evaluations=2e4,relative_target=1e-6");
    EXPECT_EQ(b.relative_target, 1e-6);
    EXPECT_FALSE(b.target_error); // resolved per problem, never set on the study's budget
    const std::string text = budget_text(b);
    EXPECT_EQ(text, "evaluations=20000,relative_target=1e-06");
    EXPECT_EQ(budget_text(parse_budget(text)), text); // run records and identities read it back alike
    EXPECT_EQ(budget_text(parse_budget("relative_target=2.5e-7,iterations=5")),
              "iterations=5,relative_target=2.5e-07");
    // f - f* <= R |f*|, for a negative f* too.
    EXPECT_EQ(b.for_problem(14, 36.099558875909494).target_error, 1e-6 * 36.099558875909494);
    EXPECT_EQ(b.for_problem(2, -50.0).target_error, 1e-6 * 50.0);
    EXPECT_EQ(b.for_problem(2, -50.0).max_evaluations, 20000);
    EXPECT_EQ(parse_budget("evaluations=10,target=1e-3").for_problem(2, 7.0).target_error, 1e-3);
    const auto refusal = [&](std::optional<double> f_opt) {
        try {
            (void)b.for_problem(2, f_opt);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(refusal(std::nullopt),
              "budget 'evaluations=20000,relative_target=1e-06': a relative target needs a known optimum");
    EXPECT_EQ(refusal(0.0),
              "budget 'evaluations=20000,relative_target=1e-06': a relative target needs a finite, "
              "non-zero f* (it stops at f - f* <= relative_target x |f*|; give target=E instead); "
              "f* = 0");
    const auto parse_error = [](const std::string& budget) {
        try {
            (void)parse_budget(budget);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(parse_error("evaluations=10,relative_target=1e-6,target=1e-8"),
              "budget 'evaluations=10,relative_target=1e-6,target=1e-8': give target=E (f - f* <= E) or "
              "relative_target=R (f - f* <= R x |f*|), not both");
    EXPECT_EQ(parse_error("evaluations=10,relative_target=-1"),
              "budget: parameter 'relative_target' = -1 is outside [0, inf]");
    EXPECT_EQ(parse_error("evaluations=10,relative_target=inf"),
              "budget: parameter 'relative_target' = inf is not a finite number");
    EXPECT_EQ(parse_error("relative_target=1e-6"),
              "budget 'relative_target=1e-6': give iterations=N and/or evaluations=N (target=E or "
              "relative_target=R is optional)");
}

// A bowl whose minimum is f* = -50 at (0.5, 0.5): a relative target of 1e-6 is f - f* <= 5e-5.
ProblemRegistry bowl_registry() {
    return test::registry_of("bowl", [](const ParameterValues&) -> std::unique_ptr<Problem> {
        return std::make_unique<test::TestProblem>(
            2, [](const Eigen::VectorXd& x) { return -50.0 + (x.array() - 0.5).square().sum(); },
            std::vector<std::string>{}, KnownOptimum{-50.0, Eigen::VectorXd::Constant(2, 0.5)});
    });
}

TEST(StudyBudget, ARunStopsAtTheRelativeTargetOfItsProblem) {
    Study s;
    s.algorithms = {"cmaes"};
    s.problems = {"bowl"};
    s.runs = 2;
    s.budgets = {parse_budget("evaluations=5000,relative_target=1e-6")};
    const PreparedStudy p = prepare_study(s, builtin_algorithms(), bowl_registry());
    EXPECT_EQ(p.request(0).budget.target_error, 1e-6 * 50.0);
    EXPECT_EQ(p.request(0).budget_text, "evaluations=5000,relative_target=1e-06");
    const RunRecord record = execute_run(p.request(0));
    ASSERT_TRUE(record.ok) << record.message;
    ASSERT_TRUE(record.evaluations_to_target.has_value());
    EXPECT_EQ(record.evaluations, *record.evaluations_to_target); // it stopped there
    EXPECT_LT(record.evaluations, 5000);
    EXPECT_LE(record.best_f - -50.0, 1e-6 * 50.0);
    EXPECT_EQ(record.budget, "evaluations=5000,relative_target=1e-06");
    // The same run as the absolute target it resolves to, but for the budget it records.
    Study absolute = s;
    absolute.budgets = {parse_budget("evaluations=5000")};
    absolute.budgets.front().target_error = 1e-6 * 50.0;
    const RunRecord same =
        execute_run(prepare_study(absolute, builtin_algorithms(), bowl_registry()).request(0));
    EXPECT_EQ(same.evaluations, record.evaluations);
    EXPECT_EQ(same.best_f, record.best_f);
    // The identity names the rule, not the resolved target.
    EXPECT_NE(run_key(p, 0).facts.find("budget = evaluations=5000,relative_target=1e-06\n"),
              std::string::npos);
    // Runs that may stop early: the dry run's count is an estimate, and shards weigh the budget.
    EXPECT_FALSE(estimate_study(p).budgets[0].exact);
    EXPECT_EQ(estimated_run_costs(p).front(), 5000.0 * 2);
}

TEST(StudyBudget, ARelativeTargetNeedsAKnownNonZeroOptimum) {
    const ProblemRegistry flat =
        test::registry_of("flat", [](const ParameterValues&) -> std::unique_ptr<Problem> {
            return std::make_unique<test::TestProblem>(1, [](const Eigen::VectorXd&) { return 0.0; });
        });
    Study s;
    s.algorithms = {"random-search"};
    s.problems = {"flat"};
    s.budgets = {parse_budget("evaluations=10,relative_target=1e-6")};
    try {
        (void)prepare_study(s, builtin_algorithms(), flat);
        ADD_FAILURE() << "no known optimum";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "budget: a relative target needs a known optimum; problem 'flat' has none");
    }
    // f* = 0: a relative target would ask for f* exactly.
    EXPECT_EQ(
        error_of(sphere_study("evaluations=10,relative_target=1e-6")),
        "budget: a relative target needs a finite, non-zero f* (it stops at f - f* <= relative_target x "
        "|f*|); problem 'sphere:dim=2' has f* = 0: give target=E instead\n"
        "budget: a relative target needs a finite, non-zero f* (it stops at f - f* <= relative_target x "
        "|f*|); problem 'sphere:dim=5' has f* = 0: give target=E instead");
    // Set in code rather than read: the same checks as target's.
    Study negative = sphere_study("evaluations=10");
    negative.problems = {"bbob:f=1,dim=2,instance=1"};
    negative.budgets.front().relative_target = -1.0;
    EXPECT_EQ(error_of(negative), "budget: relative_target = -1 is outside [0, inf)");
    negative.budgets.front().relative_target = 1e-6;
    negative.budgets.front().target_error = 1e-8;
    EXPECT_EQ(error_of(negative), "budget 'evaluations=10,target=1e-08,relative_target=1e-06': give target=E "
                                  "(f - f* <= E) or relative_target=R (f - f* <= R x |f*|), not both");
}

TEST(StudyBudget, StudyFilesAndTheCommandLineTakeARelativeTarget) {
    const Study s = parse_study_ini("algorithms = pso\nproblems = bbob:f=1,dim=2,instance=1\nruns = 2\n"
                                    "budget = evaluations=100,relative_target=1e-6\nbudget = iterations=3\n",
                                    "r.ini");
    const PreparedStudy p = prepare_study(s);
    const std::string text = study_ini(p.study);
    EXPECT_NE(text.find("budget = evaluations=100,relative_target=1e-06\nbudget = iterations=3\n"),
              std::string::npos)
        << text;
    EXPECT_EQ(study_ini(prepare_study(parse_study_ini(text, "study.ini")).study), text);
    // --relative-target (or `relative-target =`) replaces every budget's target, of either kind...
    Study overridden = s;
    overridden.budgets.front() = parse_budget("evaluations=100,target=1e-8");
    std::vector<std::string> errors;
    StudyOptionReader reader(overridden);
    reader.apply("relative-target", "1e-5", "", errors);
    reader.finish(errors);
    EXPECT_TRUE(errors.empty());
    EXPECT_EQ(budget_text(overridden.budgets[0]), "evaluations=100,relative_target=1e-05");
    EXPECT_EQ(budget_text(overridden.budgets[1]), "iterations=3,relative_target=1e-05");
    // ... as --target replaces a relative one.
    StudyOptionReader absolute(overridden);
    absolute.apply("target", "1e-3", "", errors);
    absolute.finish(errors);
    EXPECT_EQ(budget_text(overridden.budgets[0]), "evaluations=100,target=0.001");
    // Both in one source: one of them is refused where it was written.
    Study both;
    parse_study_file("relative-target = 1e-6\ntarget = 1e-8\nrelative-target = 2\n", "both.ini", both,
                     errors);
    EXPECT_EQ(errors,
              (std::vector<std::string>{
                  "both.ini:2: give target (f - f* <= E) or relative-target (f - f* <= R x |f*|), not both",
                  "both.ini:3: 'relative-target' is given twice"}));
}

TEST(StudyProtocol, AStudyFollowsACecProtocolByName) {
    const Study s =
        parse_study_ini("protocol = cec2017\nalgorithms = pso\nproblems = cec2017:f={1,3},dim=10\n"
                        "runs = 2\nbudget = evaluations=10000*dim,target=1e-8\n",
                        "cec.ini");
    EXPECT_EQ(s.protocol, "cec2017");
    const PreparedStudy p = prepare_study(s);
    EXPECT_EQ(p.request(0).budget.max_evaluations, 100000); // 10000 x D at D = 10
    const std::string text = study_ini(p.study);
    EXPECT_NE(text.find("\nprotocol = cec2017\n"), std::string::npos) << text;
    EXPECT_EQ(prepare_study(parse_study_ini(text, "study.ini")).study.protocol, "cec2017");
    // The protocol changes no run: its identity is that of the same study without it.
    Study without = s;
    without.protocol.clear();
    EXPECT_EQ(run_key(prepare_study(without), 1).identity, run_key(p, 1).identity);

    std::vector<std::string> errors;
    Study bad;
    parse_study_file("protocol = cec2014\n", "bad.ini", bad, errors);
    EXPECT_EQ(errors,
              (std::vector<std::string>{
                  "bad.ini:1: protocol = cec2014 is not one of {cec2017, cec2022, pmsm-paper, none}"}));

    Study wrong = s;
    wrong.problems = {"cec2017:f=1,dim=10", "sphere:dim=10", "bbob:f=1,dim=10"};
    wrong.budgets = {parse_budget("iterations=10")};
    EXPECT_EQ(
        error_of(wrong),
        "protocol cec2017: problems 'sphere:dim=10' and 1 more are not of the cec2017 suite; the protocol's "
        "tables and result files cover its functions only (write cec2017:f=...,dim=...)\n"
        "protocol cec2017: budget 'iterations=10' gives no evaluation count; the protocol records errors at "
        "fractions of it (write evaluations=10000*dim)");
    Study unknown = s;
    unknown.protocol = "cec2005";
    EXPECT_EQ(error_of(unknown), "protocol = cec2005 is not one of cec2017, cec2022, pmsm-paper");
}

// Run identities of a study with plain budgets, as the store of an mhbench without dimension budgets
// wrote them (`mhbench run --algorithms "tlbo pso:w=0.6" --problems "sphere:dim=3
// bbob:f=2,dim=2,instance=1" --budget iterations=5 --budget evaluations=300,target=1e-8 --budget
// iterations=4,evaluations=200 --runs 2`, built from commit 577f99c): such a study resumes from its
// store, and grows, exactly as before.
TEST(StudyBudget, IdentitiesOfExistingStudiesAreUnchanged) {
    Study s;
    s.algorithms = {"tlbo", "pso:w=0.6"};
    s.problems = {"sphere:dim=3", "bbob:f=2,dim=2,instance=1"};
    s.runs = 2;
    s.budgets = {parse_budget("iterations=5"), parse_budget("evaluations=300,target=1e-8"),
                 parse_budget("iterations=4,evaluations=200")};
    const PreparedStudy p = prepare_study(s);
    const std::vector<std::pair<std::int64_t, std::string>> pinned = {
        {0, "a17401d910951e62b9c0b1f65abac01573da3a7416151025c160a6f9081e0511"},
        {3, "4e908c70c0a977918f59dfc7c4354125af2eb5b33679ec26e5f8eca1eb230882"},
        {6, "e8a624dfcc09d56c9759a9b70dff7bafcd93da7f405a0bd66190ef7f72472d36"},
        {8, "b1b941acaff0696a70179b98f3e239d5eb5a6a572a9ee8eab8d1da7eec86a2ad"},
        {15, "bc9857a9a8a006c4055185e4dfa157bbd69eabaa36b495ff3abb2cf434a55193"},
        {16, "092a06a1f17e58683b96f1ed04d2fb46fbfe22d1585508e0936d10eb7dac91fe"},
        {23, "00eefe17795109b5c410a0aff80359b8cb655177aa336f611b573a66ac513906"},
    };
    for (const auto& [id, identity] : pinned)
        EXPECT_EQ(run_key(p, id).identity, identity) << "run " << id << ": " << run_key(p, id).slot;
    // The slot names the run by its label, which is display only: the identities above hold.
    EXPECT_EQ(run_key(p, 15).slot,
              "PSO (w=0.6) | bbob:dim=2,f=2,instance=1 | evaluations=300,target=1e-08 | 1");
}

// The dry run's report counts the figures as plot_study.py plans them (issue 37): a kind drawn per
// problem is one figure with a panel each for two to six problems, one per problem beyond; the
// fixed-target ECDF pools the problems, and the study's target adds one. The figure costs are scaled
// by this machine's speed, a positive ratio.
TEST(StudyBudget, TheReportEstimateCountsTheFiguresAsTheScriptPlansThem) {
    Study s = sphere_study("iterations=3");
    s.problems = {"sphere:dim=2", "rastrigin:dim=2"};
    s.budgets.push_back(parse_budget("evaluations=100,target=1e-8"));
    const ReportEstimate two = estimate_report(prepare_study(s), true);
    const std::vector<std::pair<std::string, std::int64_t>> expected{
        {"convergence", 3}, // by evaluations at both budgets, by iteration at the iteration budget
        {"parameters", 0},
        {"final_values", 2},
        {"ecdf", 3}, // COCO's targets twice, the study's once
        {"critical_difference", 2},
        {"effects", 0},
        {"bayesian", 2}}; // the test on both problems' medians, at each budget
    EXPECT_EQ(two.figures, expected);
    EXPECT_GT(two.speed_ratio, 0.0);
    EXPECT_GT(two.figures_seconds, 0.0);

    s.problems = {"sphere:dim=2,shift=on,instance=1-6", "rastrigin:dim=2"};
    const ReportEstimate seven = estimate_report(prepare_study(s), true);
    EXPECT_EQ(seven.figures[0].second, 3 * 7); // seven problems: a figure each
    EXPECT_EQ(seven.figures[2].second, 2 * 7);
    EXPECT_EQ(estimate_report(prepare_study(s), false).figure_count(), 0); // --no-figures
}

} // namespace
} // namespace mhb
