// `external:cmd=...` problems: the describe handshake, batch evaluation counted exactly, the
// worker pool, and every fault (crash, hang, garbage, NaN, wrong count, exit at start-up) turned
// into its one-line error and the declared policy, with no child left behind.
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <thread>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"
#include "problems/core/spec_grid.hpp"
#include "problems/external/command.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"
#include "support/external_clients.hpp"
#include "support/processes.hpp"

namespace mhb {
namespace {

using test_support::children_of_this_process;
using test_support::processes_with;
using test_support::reference_client;
using test_support::test_client;

std::unique_ptr<Problem> external(const std::string& command, const std::string& options = "") {
    return builtin_problems().create("external:cmd=" + command + (options.empty() ? "" : "," + options));
}

Eigen::VectorXd point(double a, double b) {
    Eigen::VectorXd x(2);
    x << a, b;
    return x;
}

// No live process of the test's marker (the client and what it started) and no child at all.
void expect_no_child_left(const std::string& marker) {
    EXPECT_TRUE(test_support::wait_until([&] { return processes_with(marker).empty(); }, 5.0)) << marker;
    EXPECT_TRUE(children_of_this_process().empty());
}

TEST(ExternalCommand, SplitsWordsKeepsQuotedBlanksAndOneSpecPerQuotedCommand) {
    using V = std::vector<std::string>;
    EXPECT_EQ(external::split_command("python3  model.py --fast"), (V{"python3", "model.py", "--fast"}));
    EXPECT_EQ(external::split_command("'python3 my model.py'"), (V{"python3", "my", "model.py"}));
    EXPECT_EQ(external::split_command("python3 'my model.py'"), (V{"python3", "my model.py"}));
    EXPECT_THROW((void)external::split_command("python3 'model.py"), std::invalid_argument);
    EXPECT_EQ(split_spec_list("external:cmd='python3 a.py',workers=2 pso"),
              (V{"external:cmd='python3 a.py',workers=2", "pso"}));
    EXPECT_EQ(external::split_params("external", "a=1;b=x=y"),
              (std::map<std::string, std::string>{{"a", "1"}, {"b", "x=y"}}));
}

TEST(ExternalCommand, MessagesNameTheScriptNotItsInterpreter) {
    const std::string script = std::string(MHB_SOURCE_DIR) + "/scripts/external/sphere_problem.py";
    EXPECT_EQ(external::program_name({"/usr/bin/python3", script, "dim=3"}), script);
    EXPECT_EQ(external::program_name({"python3", "-u", script}), script);
    EXPECT_EQ(external::program_name({"/usr/bin/python3", "-c", "print(1)"}), "/usr/bin/python3");
    EXPECT_EQ(external::program_name({"mymodel", "--fast"}), "mymodel");
}

TEST(ExternalProblem, DescribesItselfAndEvaluatesExactly) {
    const auto problem = external(reference_client("sphere_problem.py"), "params=dim=3");
    EXPECT_EQ(problem->name(), "external");
    ASSERT_EQ(problem->dimension(), 3);
    EXPECT_EQ(problem->bounds().lower, Eigen::VectorXd::Constant(3, -5.0));
    ASSERT_TRUE(problem->known_optimum());
    EXPECT_EQ(problem->known_optimum()->f, 0.0);
    Eigen::VectorXd x(3);
    x << 0.1, 1.0 / 3.0, -2.718281828459045;
    // Python sums left to right; %.17g and json.dumps carry every bit both ways.
    EXPECT_EQ(problem->evaluate(x), (x[0] * x[0] + x[1] * x[1]) + x[2] * x[2]);
    EXPECT_NE(problem->identity_facts().find("version sphere-1"), std::string::npos);
    // The script's content, not the interpreter's.
    EXPECT_NE(problem->identity_facts().find("sphere_problem.py; version"), std::string::npos);
    EXPECT_EQ(problem->identity_facts().find("python3;"), std::string::npos);
}

TEST(ExternalProblem, TheHeaderOnlyCppClientServesAProblem) {
    const auto problem = external(MHB_EXTERNAL_EXAMPLE_PROBLEM, "params=dim=4");
    ASSERT_EQ(problem->dimension(), 4);
    EXPECT_EQ(problem->evaluate(Eigen::VectorXd::Ones(4)), 0.0);
    Eigen::VectorXd x(4);
    x << 0.1, -1.0 / 3.0, 2.5, 1e-300;
    double f = 0.0;
    for (Eigen::Index i = 0; i + 1 < 4; ++i)
        f += 100.0 * (x[i + 1] - x[i] * x[i]) * (x[i + 1] - x[i] * x[i]) + (1.0 - x[i]) * (1.0 - x[i]);
    EXPECT_EQ(problem->evaluate(x), f);
    EXPECT_NE(problem->identity_facts().find("mhb_external_example_problem; version rosenbrock-cpp-1"),
              std::string::npos)
        << problem->identity_facts();
}

TEST(ExternalProblem, TheOctaveClientServesAProblem) {
    if (!std::filesystem::exists("/usr/bin/octave"))
        GTEST_SKIP() << "octave is not installed";
    const auto problem = external("/usr/bin/octave --no-gui --quiet --no-window-system --norc '" +
                                      std::string(MHB_SOURCE_DIR) + "/scripts/external/sphere_problem.m'",
                                  "params=dim=3,startup_timeout=60");
    ASSERT_EQ(problem->dimension(), 3);
    Eigen::VectorXd x(3);
    x << 0.1, 1.0 / 3.0, -2.0;
    EXPECT_NEAR(problem->evaluate(x), x.squaredNorm(), 1e-15);
    std::vector<Eigen::VectorXd> points{x, x};
    std::vector<double> f(2);
    problem->evaluate_many(points, f);
    EXPECT_NEAR(f[1], x.squaredNorm(), 1e-15);
}

// The worked example: the PMSM steady-state model written in Python gives the built-in
// model's numbers to 1e-12, and ITLBO identifies the motor through it as through the built-in.
TEST(ExternalProblem, ThePythonPmsmModelEqualsTheBuiltInAndItlboIdentifiesThroughIt) {
    const std::string data = std::string(MHB_TEST_DATA_DIR) + "/pmsm/pmsm_public_2200rpm_2.5Nm_clean_ss.csv";
    const auto python = external(reference_client("pmsm_steady_problem.py"), "params=data=" + data);
    const auto builtin = builtin_problems().create("pmsm:data=" + data + ",fitness=direct");
    ASSERT_EQ(python->dimension(), 4);
    EXPECT_EQ(python->bounds().lower, builtin->bounds().lower);
    EXPECT_EQ(python->bounds().upper, builtin->bounds().upper);
    EXPECT_EQ(python->parameter_names(), builtin->parameter_names());
    // The motor's parameters, from the dataset's metadata lines, as the built-in reads them.
    ASSERT_TRUE(python->true_parameters());
    EXPECT_EQ(*python->true_parameters(), *builtin->true_parameters());
    Rng rng(3);
    std::vector<Eigen::VectorXd> points{*builtin->true_parameters(), builtin->known_optimum()->x.value()};
    for (int i = 0; i < 30; ++i)
        points.push_back(uniform_point(builtin->bounds(), rng));
    std::vector<double> f(points.size());
    python->evaluate_many(points, f);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double expected = builtin->evaluate(points[i]);
        EXPECT_LE(std::fabs(f[i] - expected), 1e-12 * std::fabs(expected))
            << i << ": " << f[i] << " vs " << expected;
    }
    const auto itlbo = builtin_algorithms().create("itlbo:np=10");
    const auto identify = [&](const Problem& problem) {
        Objective objective(problem, Budget{1000, std::nullopt, std::nullopt});
        Rng stream(11);
        run_to_budget(*itlbo, objective, stream);
        return std::make_pair(objective.best_f(), objective.best_x());
    };
    const auto [python_f, python_x] = identify(*python);
    const auto [builtin_f, builtin_x] = identify(*builtin);
    EXPECT_LE(std::fabs(python_f - builtin_f), 1e-12 * builtin_f);
    EXPECT_LE((python_x - builtin_x).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(ExternalProblem, ABatchThatCrossesTheBudgetIsEvaluatedExactlyUpToIt) {
    const auto problem = external(reference_client("sphere_problem.py"), "params=dim=2");
    Objective objective(*problem, Budget{7, std::nullopt, std::nullopt});
    std::vector<Eigen::VectorXd> x;
    for (int i = 0; i < 10; ++i)
        x.push_back(point(0.5 * i, -0.5 * i));
    std::vector<double> f(10, -1.0);
    EXPECT_THROW(objective.evaluate_batch(x, f), BudgetExhausted);
    EXPECT_EQ(objective.evaluations(), 7);
    for (int i = 0; i < 7; ++i)
        EXPECT_EQ(f[static_cast<std::size_t>(i)], 0.5 * i * i);
    EXPECT_EQ(f[7], -1.0);
}

TEST(ExternalProblem, APoolOfWorkersServesManyThreads) {
    const std::string marker = "pool-marker-1";
    {
        const auto problem = external(test_client("faulty_problem.py", "ok 0 " + marker), "workers=2");
        std::vector<std::thread> threads;
        std::vector<double> sums(4, 0.0);
        for (std::size_t t = 0; t < 4; ++t)
            threads.emplace_back([&, t] {
                for (int i = 0; i < 20; ++i)
                    sums[t] += problem->evaluate(point(static_cast<double>(t), i));
            });
        for (auto& thread : threads)
            thread.join();
        for (std::size_t t = 0; t < 4; ++t)
            EXPECT_EQ(sums[t], 20.0 * static_cast<double>(t * t) + 2470.0);
        EXPECT_LE(processes_with(marker).size(), 2U);
        // A batch is split across the workers (never more than `workers` processes).
        std::vector<Eigen::VectorXd> x(6, point(1, 1));
        std::vector<double> f(6);
        problem->evaluate_many(x, f);
        EXPECT_EQ(f, std::vector<double>(6, 2.0));
        EXPECT_GE(processes_with(marker).size(), 1U);
        EXPECT_LE(processes_with(marker).size(), 2U);
    }
    expect_no_child_left(marker);
}

struct Fault {
    std::string mode;
    std::string message; // what the one-line error must say
};

class ExternalProblemFault : public testing::TestWithParam<Fault> {};

TEST_P(ExternalProblemFault, FailPolicyFailsWithOneLineAndTheNextCallRestartsTheWorker) {
    const std::string marker = "fault-fail-" + GetParam().mode;
    {
        const auto problem =
            external(test_client("faulty_problem.py", GetParam().mode + " 2 " + marker), "timeout=0.3");
        EXPECT_EQ(problem->evaluate(point(1, 2)), 5.0);
        std::vector<Eigen::VectorXd> x{point(1, 0), point(0, 1)};
        std::vector<double> f(2);
        try {
            problem->evaluate_many(x, f);
            ADD_FAILURE() << "no error";
        } catch (const std::runtime_error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("external problem '"), std::string::npos) << what;
            EXPECT_NE(what.find(GetParam().message), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
        // The worker was killed with its group; the next evaluation starts a fresh one.
        EXPECT_TRUE(test_support::wait_until([&] { return processes_with(marker).size() <= 1; }, 5.0));
        EXPECT_EQ(problem->evaluate(point(3, 4)), 25.0);
    }
    expect_no_child_left(marker);
}

TEST_P(ExternalProblemFault, InfPolicyGivesInfinityToThePointsInFlight) {
    const std::string marker = "fault-inf-" + GetParam().mode;
    {
        const auto problem = external(test_client("faulty_problem.py", GetParam().mode + " 2 " + marker),
                                      "timeout=0.3,on_failure=inf");
        Objective objective(*problem, Budget{100, std::nullopt, std::nullopt});
        std::vector<Eigen::VectorXd> x{point(1, 0), point(0, 1), point(1, 1)};
        std::vector<double> f(3);
        objective.evaluate_batch(x, f); // message 1
        EXPECT_EQ(f, (std::vector<double>{1.0, 1.0, 2.0}));
        objective.evaluate_batch(x, f); // message 2: the fault
        EXPECT_TRUE(std::isinf(f[0]) && std::isinf(f[1]) && std::isinf(f[2]));
        objective.evaluate_batch(x, f); // a new worker
        EXPECT_EQ(f, (std::vector<double>{1.0, 1.0, 2.0}));
        EXPECT_EQ(objective.evaluations(), 9);
    }
    expect_no_child_left(marker);
}

INSTANTIATE_TEST_SUITE_P(
    Faults, ExternalProblemFault,
    testing::Values(Fault{"crash", "exited with status 3; its stderr: faulty: segmentation"},
                    Fault{"hang", "did not answer within"},
                    Fault{"garbage", "faulty_problem.py: wrote a line that is not a JSON object ('Warning: "
                                     "model converged slowly'): stdout carries the protocol; print "
                                     "your own output to stderr"},
                    Fault{"nan", "returned NaN for point 1 of 2"}, Fault{"count", "f has 1 numbers, not 2"}),
    [](const auto& test) { return test.param.mode; });

TEST(ExternalProblem, PastTheRestartLimitTheRunFailsWhateverThePolicy) {
    const std::string marker = "restart-limit";
    {
        const auto problem =
            external(test_client("faulty_problem.py", "crash 1 " + marker), "on_failure=inf,restarts=2");
        EXPECT_TRUE(std::isinf(problem->evaluate(point(1, 1))));
        EXPECT_TRUE(std::isinf(problem->evaluate(point(1, 1))));
        try {
            (void)problem->evaluate(point(1, 1));
            ADD_FAILURE() << "no error";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("3 faults in a row of one worker: given up"),
                      std::string::npos)
                << e.what();
        }
    }
    expect_no_child_left(marker);
}

TEST(ExternalProblem, ADeclaredTruthIsItsTrueParametersAndOutsideTheBoxAWarning) {
    {
        const auto inside = external(test_client("truth_problem.py"), "params=truth=1:-2");
        ASSERT_TRUE(inside->true_parameters());
        EXPECT_EQ(*inside->true_parameters(), point(1, -2));
        EXPECT_TRUE(inside->warnings().empty());
        const auto outside = external(test_client("truth_problem.py"), "params=truth=7:0");
        ASSERT_EQ(outside->warnings().size(), 1U);
        EXPECT_NE(outside->warnings()[0].find("the truth it declares lies outside its box"),
                  std::string::npos);
        EXPECT_FALSE(external(reference_client("sphere_problem.py"), "params=dim=2")->true_parameters());
    }
    EXPECT_TRUE(children_of_this_process().empty());
}

TEST(ExternalProblem, ATruthOfTheWrongSizeNotFiniteOrUnnamedIsAConfigurationError) {
    const std::pair<const char*, const char*> cases[] = {
        {"truth=1", "truth has 1 numbers, not 2"},
        {"truth=1:inf", "\"truth\" holds a value that is not a finite number"},
        {"truth=1:nan", "\"truth\" holds a value that is not a finite number"},
        {"truth=1:2;names=0", "\"truth\" needs \"names\""},
    };
    for (const auto& [params, message] : cases) {
        try {
            (void)external(test_client("truth_problem.py"), std::string("params=") + params);
            ADD_FAILURE() << params << ": no error";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << params << ": " << e.what();
        }
    }
    EXPECT_TRUE(children_of_this_process().empty());
}

TEST(ExternalProblem, AProgramThatExitsAtStartUpIsAConfigurationError) {
    try {
        (void)external(test_client("faulty_problem.py", "startup 0 startup-marker"));
        ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("exited with status 2; its stderr: faulty: cannot load the model"),
                  std::string::npos)
            << what;
    }
    try {
        (void)external("/nonexistent/model");
        ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/model cannot be run"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW((void)builtin_problems().create("external:workers=2"), std::invalid_argument);
    EXPECT_TRUE(children_of_this_process().empty());
}

} // namespace
} // namespace mhb
