// `mhbench plugin-check --algorithm SPEC | --problem SPEC`: the checks of runner/plugins/plugin_check.hpp
// on a user's optimiser or problem (or a built-in one), one line each, exit 1 when any fails.
#include <algorithm>
#include <boost/program_options.hpp>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"
#include "runner/plugins/components.hpp"
#include "runner/plugins/plugin_check.hpp"

namespace mhb::cli {
namespace {

// The problem an optimiser is checked on when none is given, and the optimiser a problem is run
// by: cheap, and every coordinate of the box matters.
constexpr const char* default_problem = "rastrigin:dim=10";
constexpr const char* default_algorithm = "random-search";

// Each check's line under `heading`; with `quiet`, the failed ones only (and the heading when one
// failed). Returns whether none failed.
bool print_results(const std::string& heading, const std::vector<CheckResult>& results, bool quiet) {
    const bool failed = std::any_of(results.begin(), results.end(),
                                    [](const CheckResult& r) { return r.verdict == CheckVerdict::fail; });
    if (quiet && !failed)
        return true;
    std::cout << heading << '\n';
    for (const CheckResult& r : results) {
        if (quiet && r.verdict != CheckVerdict::fail)
            continue;
        char name[32];
        std::snprintf(name, sizeof name, "%-13s", r.name.c_str());
        std::cout << "  " << to_string(r.verdict) << "  " << name << r.detail << '\n';
    }
    return !failed;
}

} // namespace

int run_plugin_check_command(const std::vector<std::string>& args) {
    namespace po = boost::program_options;
    po::options_description options(
        "mhbench plugin-check: is an optimiser or a problem fit for a study? One line a check, exit 1 when "
        "one "
        "fails.\n\nAn optimiser (on --problem, default rastrigin:dim=10): its runs finish, every point "
        "evaluated is in the box, each run spends exactly its budget, the same seed gives the same record "
        "bit for bit, and the runs do not depend on the number of threads. A problem: its box and known "
        "optimum hold together, its values are numbers (never NaN, never below f*), the same point gives "
        "the same value again and on other threads, what one evaluation costs; then random-search runs on "
        "it through the optimiser checks.\n\nUsage: mhbench plugin-check --algorithm SPEC [--problem SPEC]\n"
        "       mhbench plugin-check --problem SPEC\n"
        "       mhbench plugin-check --plugin my_module.so --algorithm my-optimizer\n\nOptions");
    options.add_options()("help,h", "this text")("algorithm", po::value<std::string>(),
                                                 "the optimiser to check (mhbench list algorithms)")(
        "problem", po::value<std::string>(), "the problem to check, or to check the optimiser on")(
        "evaluations", po::value<std::string>()->default_value("2000"), "budget of each optimiser run")(
        "runs", po::value<std::string>()->default_value("4"), "optimiser runs, each with its own seed")(
        "seed", po::value<std::string>()->default_value("1"),
        "the seed the runs' seeds derive from")("threads", po::value<std::string>()->default_value("2"),
                                                "threads of the parallel side of the checks")(
        "points", po::value<std::string>()->default_value("2000"), "random points a problem is evaluated at")(
        "plugin", po::value<std::vector<std::string>>()->composing(),
        "load this plug-in module first, so that --algorithm and --problem may name its components "
        "(repeatable)")("quiet,q", "print the failed checks and the verdict only");
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { std::cout << options << '\n'; }))
        return exit_ok;
    if (vm.count("algorithm") == 0 && vm.count("problem") == 0)
        throw po::error("give --algorithm SPEC, --problem SPEC or both");
    PluginCheckOptions check;
    check.evaluations = integer_argument(vm["evaluations"].as<std::string>(), "evaluations", 1, 100000000);
    check.runs = static_cast<int>(integer_argument(vm["runs"].as<std::string>(), "runs", 1, 1000));
    check.seed = static_cast<std::uint64_t>(
        integer_argument(vm["seed"].as<std::string>(), "seed", 0, std::numeric_limits<long long>::max()));
    check.threads = static_cast<int>(integer_argument(vm["threads"].as<std::string>(), "threads", 2, 1024));
    check.points = integer_argument(vm["points"].as<std::string>(), "points", 1, 100000000);

    const Components components = compose_components(
        vm.count("plugin") != 0 ? vm["plugin"].as<std::vector<std::string>>() : std::vector<std::string>{});
    const AlgorithmRegistry& algorithms = components.algorithms;
    const ProblemRegistry& problems = components.problems;
    const Spec problem_spec = problems.normalised(
        Spec::parse(vm.count("problem") != 0 ? vm["problem"].as<std::string>() : default_problem));
    const Spec algorithm_spec = algorithms.normalised(
        Spec::parse(vm.count("algorithm") != 0 ? vm["algorithm"].as<std::string>() : default_algorithm));
    const auto problem = problems.create(problem_spec);
    const auto optimizer = algorithms.create(algorithm_spec);

    const bool quiet = vm.count("quiet") != 0;
    bool passed = true;
    if (vm.count("problem") != 0)
        passed = print_results("problem " + problem_spec.canonical() + ":", check_problem(*problem, check),
                               quiet) &&
                 passed;
    passed = print_results(algorithm_spec.canonical() + " on " + problem_spec.canonical() + " (" +
                               std::to_string(check.runs) + " runs of " + std::to_string(check.evaluations) +
                               " evaluations):",
                           check_optimizer(*optimizer, algorithm_spec.canonical(), *problem,
                                           problem_spec.canonical(), check),
                           quiet) &&
             passed;
    std::cout << (passed ? "verdict: pass\n" : "verdict: FAIL\n");
    return passed ? exit_ok : exit_failure;
}

} // namespace mhb::cli
