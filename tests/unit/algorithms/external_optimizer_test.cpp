// `external:cmd=...` optimisers: the child drives, mhbench counts. A batch that crosses the end
// of the budget is evaluated exactly up to it; points outside the box come back repaired; the
// same seed gives the same numbers; a child that crashes or hangs fails the run with one line
// and leaves no process behind.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "algorithms/algorithm_registry.hpp"
#include "problems/problem_registry.hpp"
#include "support/external_clients.hpp"
#include "support/processes.hpp"

namespace mhb {
namespace {

using test_support::children_of_this_process;
using test_support::processes_with;
using test_support::reference_client;
using test_support::test_client;

std::unique_ptr<Optimizer> external(const std::string& command, const std::string& options = "") {
    return builtin_algorithms().create("external:cmd=" + command + (options.empty() ? "" : "," + options));
}

std::vector<std::string> lines_of(const std::filesystem::path& path) {
    std::vector<std::string> lines;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

TEST(ExternalOptimizer, ABatchThatCrossesTheBudgetIsEvaluatedExactlyUpToItThenStop) {
    const auto log =
        std::filesystem::temp_directory_path() / ("mhb_external_log_" + std::to_string(::getpid()));
    std::filesystem::remove(log);
    const auto problem = builtin_problems().create("sphere:dim=2");
    const auto optimizer =
        external(test_client("faulty_optimizer.py", "ok 10 count-marker '" + log.string() + "'"));
    Objective objective(*problem, Budget{25, std::nullopt, std::nullopt});
    Rng rng(7);
    run_to_budget(*optimizer, objective, rng);
    EXPECT_EQ(objective.evaluations(), 25);
    const auto lines = lines_of(log);
    ASSERT_EQ(lines.size(), 3U);
    EXPECT_EQ(lines[0].substr(0, 15), "reply 10 10 10 ");
    EXPECT_EQ(lines[1].substr(0, 15), "reply 10 10 20 ");
    EXPECT_EQ(lines[2].substr(0, 12), "reply 5 5 25");
    std::filesystem::remove(log);
    EXPECT_TRUE(test_support::wait_until([] { return processes_with("count-marker").empty(); }, 5.0));
    EXPECT_TRUE(children_of_this_process().empty());
}

TEST(ExternalOptimizer, PointsOutsideTheBoxComeBackRepaired) {
    const auto log =
        std::filesystem::temp_directory_path() / ("mhb_external_clamp_" + std::to_string(::getpid()));
    std::filesystem::remove(log);
    const auto problem = builtin_problems().create("sphere:dim=2");
    const auto optimizer =
        external(test_client("faulty_optimizer.py", "outside 50 clamp-marker '" + log.string() + "'"));
    Objective objective(*problem, Budget{2000, std::nullopt, std::nullopt});
    Rng rng(7);
    run_to_budget(*optimizer, objective, rng);
    for (const auto& line : lines_of(log))
        EXPECT_LE(std::stod(line.substr(line.rfind(' ') + 1)), problem->bounds().upper[0]) << line;
    EXPECT_TRUE(problem->bounds().contains(objective.best_x()));
    std::filesystem::remove(log);
}

TEST(ExternalOptimizer, TheSameSeedGivesTheSameNumbers) {
    const auto problem = builtin_problems().create("sphere:dim=3");
    const auto optimizer = external(reference_client("one_plus_one_es.py"), "params=lambda=4");
    const auto best = [&](std::uint64_t seed) {
        Objective objective(*problem, Budget{200, std::nullopt, std::nullopt});
        Rng rng(seed);
        run_to_budget(*optimizer, objective, rng);
        EXPECT_EQ(objective.evaluations(), 200);
        EXPECT_GT(objective.iterations(), 0);
        return objective.best_f();
    };
    const double first = best(11);
    EXPECT_EQ(best(11), first);
    EXPECT_NE(best(12), first);
    EXPECT_LT(first, 10.0); // it optimises: sphere's box is wide
    EXPECT_NE(optimizer->identity_facts().find("version es-1"), std::string::npos);
}

TEST(ExternalOptimizer, EarlyDoneEndsTheRunWithWhatWasEvaluated) {
    const auto problem = builtin_problems().create("sphere:dim=2");
    const auto optimizer = external(test_client("faulty_optimizer.py", "done 3 done-marker"));
    Objective objective(*problem, Budget{100, std::nullopt, std::nullopt});
    Rng rng(1);
    run_to_budget(*optimizer, objective, rng);
    EXPECT_EQ(objective.evaluations(), 6);
}

TEST(ExternalOptimizer, ABudgetOfIterationsAloneIsRefusedBeforeTheProgramStarts) {
    const auto problem = builtin_problems().create("sphere:dim=2");
    const auto optimizer = external(test_client("faulty_optimizer.py", "done 3 iterations-marker"));
    Objective objective(*problem, Budget{std::nullopt, 10, std::nullopt});
    Rng rng(1);
    try {
        run_to_budget(*optimizer, objective, rng);
        ADD_FAILURE() << "an external optimiser ran with iterations alone";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("needs an evaluation budget (--evaluations N"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(objective.evaluations(), 0);
}

TEST(ExternalOptimizer, ACrashOrAHangFailsTheRunWithOneLineAndNoProcessLeft) {
    const auto problem = builtin_problems().create("sphere:dim=2");
    for (const auto& [mode, message] : std::vector<std::pair<std::string, std::string>>{
             {"crash", "exited with status 4"}, {"hang", "did not answer within"}}) {
        const std::string marker = "optimizer-fault-" + mode;
        const auto optimizer =
            external(test_client("faulty_optimizer.py", mode + " 3 " + marker), "timeout=0.3");
        Objective objective(*problem, Budget{100, std::nullopt, std::nullopt});
        Rng rng(1);
        try {
            run_to_budget(*optimizer, objective, rng);
            ADD_FAILURE() << mode << ": no error";
        } catch (const std::runtime_error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("external optimizer '"), std::string::npos) << what;
            EXPECT_NE(what.find(message), std::string::npos) << what;
            EXPECT_NE(what.find("reply 3 3 6"), std::string::npos) << what; // its last stderr lines
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
        EXPECT_EQ(objective.evaluations(), 6);
        EXPECT_TRUE(test_support::wait_until([&] { return processes_with(marker).empty(); }, 5.0)) << marker;
        EXPECT_TRUE(children_of_this_process().empty());
    }
}

} // namespace
} // namespace mhb
