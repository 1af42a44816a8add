// Studies: expansion of problem ranges, the fixed run numbering, every configuration error
// reported at once, the study.ini round trip, and the presets' contents.
#include <algorithm>
#include <gtest/gtest.h>
#include <set>
#include <sstream>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/rng.hpp"
#include "problems/problem_registry.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "runner/study/study_presets.hpp"
#include "tests/support/prepared_study.hpp"
#include "tests/unit/runner/test_problem.hpp"

namespace mhb {
namespace {

// The registry's own list, so the expectation follows as optimisers are added.
std::string known_algorithm_names() {
    std::string names;
    for (const auto& e : builtin_algorithms().entries())
        names += (names.empty() ? "" : ", ") + e.name;
    return names;
}

// The built-in sphere with its dimension declared as a range parameter, the way families such as
// bbob declare `f` and `instance` (sphere itself does not), so expansion can be tested here.
const ProblemRegistry& ranged_problems() {
    static const ProblemRegistry registry = [] {
        ProblemRegistry r("problem");
        auto entry = builtin_problems().find("sphere");
        for (auto& p : entry.parameters)
            p.allows_range = p.allows_range || p.name == "dim";
        r.add(entry);
        return r;
    }();
    return registry;
}

PreparedStudy prepare(const Study& s) {
    return prepare_study(s, builtin_algorithms(), ranged_problems());
}

Study small_random_search_study() {
    Study s;
    s.algorithms = {"random-search:batch=4", "random-search:batch=7"};
    s.problems = {"sphere:dim=1-3", "sphere:bound=5,dim=2"};
    s.runs = 3;
    s.seed = 42;
    s.budgets.front().max_iterations = 5;
    return s;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

TEST(Study, ExpandsProblemRangesInPlaceAndNumbersRunsProblemAlgorithmRun) {
    const PreparedStudy p = prepare(small_random_search_study());
    // sphere:dim=1-3 becomes three problems, then the explicit one: 4 problems x 2 algorithms x 3 runs.
    EXPECT_EQ(
        test_support::problem_specs(p),
        (std::vector<std::string>{"sphere:dim=1", "sphere:dim=2", "sphere:dim=3", "sphere:bound=5,dim=2"}));
    EXPECT_EQ(test_support::algorithm_specs(p),
              (std::vector<std::string>{"random-search:batch=4", "random-search:batch=7"}));
    ASSERT_EQ(p.run_count(), 24);
    std::set<std::tuple<std::string, std::string, std::int64_t>> seen;
    for (std::int64_t id = 0; id < p.run_count(); ++id) {
        const RunRequest r = p.request(id);
        EXPECT_EQ(r.run_id, id);
        // The documented order: problem outermost, then algorithm, then run index.
        const auto pi = static_cast<std::size_t>(id / 6);
        const auto ai = static_cast<std::size_t>((id / 3) % 2);
        EXPECT_EQ(r.problem_spec, p.problems[pi].spec);
        EXPECT_EQ(r.algorithm_spec, p.algorithms[ai].info.spec);
        EXPECT_EQ(r.run_index, id % 3);
        EXPECT_EQ(r.problem, p.problems[pi].problem.get()); // components built once, shared by their runs
        EXPECT_EQ(r.optimizer, p.algorithms[ai].optimizer.get());
        // Common random numbers: the seed depends on the problem and the run index only.
        EXPECT_EQ(r.seed, derive_seed(42, r.problem_spec, static_cast<std::uint64_t>(r.run_index)));
        EXPECT_EQ(r.budget_text, "iterations=5");
        EXPECT_EQ(r.budget.max_iterations, 5);
        seen.insert({r.problem_spec, r.algorithm_spec, r.run_index});
    }
    EXPECT_EQ(seen.size(), 24u); // every (problem, algorithm, run) exactly once
    EXPECT_EQ(p.problems[2].problem->dimension(), 3);
    EXPECT_THROW((void)p.request(24), std::out_of_range);
    EXPECT_THROW((void)p.request(-1), std::out_of_range);
}

TEST(Study, SpecsAreCanonicalSoParameterOrderDoesNotMatter) {
    Study a = small_random_search_study();
    Study b = small_random_search_study();
    b.problems = {"sphere:dim=1-3", "sphere:dim=2,bound=5"};
    EXPECT_EQ(test_support::problem_specs(prepare(a)), test_support::problem_specs(prepare(b)));
    EXPECT_EQ(study_ini(prepare(a).study), study_ini(prepare(b).study));
}

TEST(Study, ReportsEveryErrorAtOnceOneLineEach) {
    Study s;
    s.algorithms = {"random-search:batch=0", "nope", "random-search:batch=0,speed=3", "pso:w"};
    s.problems = {"sphere:dim=0"};
    s.runs = 0;
    s.budgets.front().max_iterations = -1;
    s.budgets.front().target_error = -1.0;
    try {
        (void)prepare(s);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        const auto lines = lines_of(e.what());
        // Spec by spec, in the order written, then the study's own settings.
        const std::vector<std::string> expected = {
            "random-search: parameter 'batch' = 0 is outside [1, 1000000000]",
            "unknown algorithm 'nope'; known: " + known_algorithm_names(),
            "random-search: parameter 'batch' = 0 is outside [1, 1000000000]",
            "random-search: unknown parameter 'speed'; known: batch",
            "algorithm 'pso:w': w is not key=value",
            "sphere: parameter 'dim' = 0 is outside [1, 10000]",
            "study: runs = 0 is outside [1, 1000000]",
            "budget: iterations = -1 is outside [1, inf)",
            "budget: target = -1 is outside [0, inf)",
        };
        EXPECT_EQ(lines, expected);
    }
}

TEST(Study, RejectsRepeatedSpecsAMissingBudgetAndATargetWithoutOptimum) {
    Study s;
    s.algorithms = {"random-search:batch=3", "random-search:batch=3"};
    s.problems = {"sphere:dim=2-3", "sphere:dim=3"};
    try {
        (void)prepare(s);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(lines_of(e.what()), (std::vector<std::string>{
                                          "algorithm 'random-search:batch=3' is the same optimiser as "
                                          "'random-search:batch=3' (both are 'random-search:batch=3')",
                                          "problem 'sphere:dim=3' is the same problem as 'sphere:dim=3'",
                                          "budget: give a number of iterations or of evaluations (or both)",
                                      }));
    }
    // A target needs f*; a registry with a problem that has none shows the check.
    const ProblemRegistry problems =
        test::registry_of("flat", [](const ParameterValues&) -> std::unique_ptr<Problem> {
            return std::make_unique<test::TestProblem>(1, [](const Eigen::VectorXd&) { return 0.0; });
        });
    Study t;
    t.algorithms = {"random-search"};
    t.problems = {"flat"};
    t.budgets.front().max_evaluations = 10;
    t.budgets.front().target_error = 1e-3;
    EXPECT_THROW(
        {
            try {
                (void)prepare_study(t, builtin_algorithms(), problems);
            } catch (const std::invalid_argument& e) {
                EXPECT_STREQ(e.what(), "budget: a target needs a known optimum; problem 'flat' has none");
                throw;
            }
        },
        std::invalid_argument);
}

TEST(Study, ParameterColumnsAreTheUnionOfNamedParametersInOrder) {
    // Test functions have no named parameters, so a sphere study has no parameter columns.
    EXPECT_TRUE(prepare(small_random_search_study()).parameter_columns.empty());
    // Identification problems name theirs; runs.csv gets the union, in order of first appearance.
    const ProblemRegistry problems =
        test::registry_of("named",
                          [](const ParameterValues& v) -> std::unique_ptr<Problem> {
                              auto names = v.boolean("swap") ? std::vector<std::string>{"c", "b"}
                                                             : std::vector<std::string>{"a", "b"};
                              return std::make_unique<test::TestProblem>(
                                  2, [](const Eigen::VectorXd& x) { return x.sum(); }, std::move(names));
                          },
                          {ParameterInfo::boolean("swap", false, "name the parameters c, b")});
    Study s;
    s.algorithms = {"random-search"};
    s.problems = {"named", "named:swap=on"};
    s.budgets.front().max_iterations = 1;
    EXPECT_EQ(prepare_study(s, builtin_algorithms(), problems).parameter_columns,
              (std::vector<std::string>{"a", "b", "c"}));
}

TEST(StudyFile, RoundTripsTheSameStudy) {
    Study s = small_random_search_study();
    s.budgets.front().max_evaluations = 1234;
    s.budgets.front().target_error = 1e-8;
    s.seed = 18446744073709551615ULL; // the largest seed must survive the text
    const PreparedStudy p = prepare(s);
    const std::string text = study_ini(p.study);
    const Study back = parse_study_ini(text, "study.ini");
    EXPECT_EQ(back.algorithms, p.study.algorithms);
    EXPECT_EQ(back.problems, (std::vector<std::string>{"sphere:dim=1-3", "sphere:bound=5,dim=2"}));
    EXPECT_EQ(back.runs, 3);
    EXPECT_EQ(back.seed, 18446744073709551615ULL);
    EXPECT_EQ(back.budgets.front().max_iterations, 5);
    EXPECT_EQ(back.budgets.front().max_evaluations, 1234);
    EXPECT_EQ(back.budgets.front().target_error, 1e-8);
    EXPECT_EQ(study_ini(back), text); // a fixed point: re-serialising gives the same bytes
    // The same study again: same runs, same seeds.
    const PreparedStudy q = prepare(back);
    ASSERT_EQ(q.run_count(), p.run_count());
    for (std::int64_t id = 0; id < p.run_count(); ++id) {
        EXPECT_EQ(q.request(id).algorithm_spec, p.request(id).algorithm_spec);
        EXPECT_EQ(q.request(id).problem_spec, p.request(id).problem_spec);
    }
    // Nothing machine-dependent: threads and output directory are not part of a study.
    std::set<std::string> keys;
    for (const auto& line : lines_of(text))
        if (!line.empty() && line[0] != '#')
            keys.insert(line.substr(0, line.find(' ')));
    EXPECT_EQ(keys, (std::set<std::string>{"algorithms", "problems", "runs", "seed", "seeds", "budget"}));
}

TEST(StudyFile, ReadsConfigSyntaxWithCommentsAndNamesTheKeyOfAnError) {
    const Study s =
        parse_study_ini("# a comment\n\n  algorithm = random-search:batch=3   # trailing comment\r\n"
                        "problem=sphere\nruns = 1e1\niterations = 7\nalgorithm = a  b:c=1\n",
                        "f.ini");
    EXPECT_EQ(s.algorithms, (std::vector<std::string>{"random-search:batch=3", "a", "b:c=1"}));
    EXPECT_EQ(s.problems, (std::vector<std::string>{"sphere"}));
    EXPECT_EQ(s.runs, 10);
    EXPECT_EQ(s.budgets.front().max_iterations, 7);
    EXPECT_FALSE(s.budgets.front().max_evaluations.has_value());
    const auto message = [](const std::string& text) {
        try {
            (void)parse_study_ini(text, "f.ini");
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(
        message("runs = 2\nthreads = 4\n"),
        "f.ini:2: unknown key 'threads' (it is not part of a study: give --threads on the command line)");
    EXPECT_EQ(message("runs = two\n"), "f.ini:1: runs = two is not an integer");
    EXPECT_EQ(message("seed = -1\n"), "f.ini:1: seed = -1 is not an integer in [0, 2^64)");
    EXPECT_EQ(message("iterations = 3\niterations = 4\n"), "f.ini:2: 'iterations' is given twice");
    EXPECT_EQ(message("algorithm\n"), "f.ini:1: 'algorithm' is not key = value");
    // Several lines and none of them key = value: not a study file, said in one line.
    EXPECT_EQ(message("algorithm\nproblem\n"), "f.ini: is not a study file (no line is key = value; line 1: "
                                               "'algorithm' is not key = value, and 1 more like it)");
}

TEST(StudyPresets, PaperPresetIsThePapersSetup) {
    // Li, Wang and Ji (2017), section 4: ITLBO, TLBO and PSO with NP = 50 (the defaults),
    // 150 iterations, 20 runs, at 2500 rpm and 2 N.m.
    const Study& s = find_study_preset("paper").study;
    EXPECT_EQ(s.algorithms, (std::vector<std::string>{"itlbo", "tlbo", "pso"}));
    EXPECT_EQ(s.problems, (std::vector<std::string>{"pmsm:speed=2500,load=2"}));
    EXPECT_EQ(s.runs, 20);
    EXPECT_EQ(s.seed, 1u);
    EXPECT_EQ(s.budgets.front().max_iterations, 150);
    EXPECT_FALSE(s.budgets.front().max_evaluations.has_value());
    EXPECT_FALSE(s.budgets.front().target_error.has_value());
}

TEST(StudyPresets, BiasPresetAuditsItlbosEightVariantsOnF0) {
    // ITLBO's 2^3 design as the ablation preset writes it, f0 at D = 30, 100 runs, 10^4 D evaluations.
    const PreparedStudy bias = prepare_study(find_study_preset("bias").study);
    EXPECT_EQ(bias.algorithms.size(), 8U);
    ASSERT_EQ(bias.problems.size(), 1U);
    EXPECT_EQ(bias.problems.front().spec, "f0:dim=30");
    EXPECT_EQ(bias.study.runs, 100);
    EXPECT_EQ(bias.budget_texts, (std::vector<std::string>{"evaluations=300000"}));
    EXPECT_EQ(bias.algorithms.front().info.label, "itlbo[T+S+O+]");
}

TEST(StudyPresets, NamesAreUniqueUnknownNamesListTheKnownOnesAndEveryPresetIsValid) {
    std::set<std::string> names;
    std::string known;
    for (const auto& p : study_presets()) {
        EXPECT_TRUE(names.insert(p.name).second) << p.name;
        EXPECT_FALSE(p.summary.empty());
        known += (known.empty() ? "" : ", ") + p.name;
        // Every preset names registered components with valid parameters.
        EXPECT_NO_THROW((void)prepare_study(p.study)) << p.name;
    }
    EXPECT_TRUE(std::is_sorted(study_presets().begin(), study_presets().end(),
                               [](const auto& a, const auto& b) { return a.name < b.name; }));
    try {
        (void)find_study_preset("nope");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(e.what(), "unknown study 'nope'; known: " + known);
    }
    const PreparedStudy smoke = prepare_study(find_study_preset("smoke").study);
    EXPECT_EQ(smoke.run_count(), 10);
}

} // namespace
} // namespace mhb
