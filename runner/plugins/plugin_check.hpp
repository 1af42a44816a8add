// `mhbench plugin-check`: what a user's optimiser or problem must do to be benchmarked honestly,
// checked on a small case before a study spends days on it. For an optimiser: its runs finish,
// every point it has evaluated lies in the box, it spends exactly its budget, the same seed gives
// the same record bit for bit, and the runs do not depend on how many threads execute them. For a
// problem: its description holds together (box, known optimum), its values are numbers, the same
// point gives the same value again and on other threads, and what one evaluation costs.
//
// Works on any Optimizer or Problem, built in, from a plug-in module or an external program: the
// checks see only the contracts (algorithms/optimizer.hpp, problems/problem.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/optimizer.hpp"
#include "problems/problem.hpp"

namespace mhb {

struct PluginCheckOptions {
    std::int64_t evaluations = 2000; // per run of an optimiser
    int runs = 4;                    // runs of an optimiser, each with its own seed
    std::uint64_t seed = 1;          // the runs' seeds derive from it
    int threads = 2;                 // the parallel side of the threads check
    std::int64_t points = 2000;      // random points a problem is evaluated at
};

enum class CheckVerdict { pass, warn, fail };

struct CheckResult {
    std::string name; // short: "bounds", "budget", ...
    CheckVerdict verdict = CheckVerdict::pass;
    std::string detail; // one line: what was seen
};

// The checks of `optimizer` on `problem` (each run through the counted Objective, as in a study).
std::vector<CheckResult> check_optimizer(const Optimizer& optimizer, const std::string& algorithm_spec,
                                         const Problem& problem, const std::string& problem_spec,
                                         const PluginCheckOptions& options);

// The checks of `problem` alone, the cost per evaluation among them.
std::vector<CheckResult> check_problem(const Problem& problem, const PluginCheckOptions& options);

const char* to_string(CheckVerdict verdict);

} // namespace mhb
