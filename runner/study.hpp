// A study: every algorithm spec x every problem spec x `runs` repetitions, with one study seed
// and one budget. This is what a user describes (on the command line, in study.ini or through a
// preset); prepare_study() checks all of it at once and builds each optimiser and problem once,
// to be shared read-only by all their runs.
//
// Run numbering is fixed: run_id = (problem * algorithms + algorithm) * runs + run index, in the
// order the specs are listed (problem ranges expanded in place). Together with the seeds derived
// from (study seed, algorithm, problem, run index) this makes a study's results independent of
// how many threads execute it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"
#include "runner/execute_run.hpp"

namespace mhb {

struct Study {
    std::vector<std::string> algorithms; // specs, e.g. "pso:w=0.7"
    std::vector<std::string> problems;   // specs; integer ranges allowed, e.g. "bbob:f=1-24"
    std::int64_t runs = 20;              // repetitions of each (algorithm, problem) pair
    std::uint64_t seed = 1;
    Budget budget; // iterations and/or evaluations (whichever is spent first), optional target
};

inline constexpr std::int64_t max_runs_per_pair = 1000000;

// A validated study, ready to run.
struct PreparedStudy {
    Study study;                              // with every spec in canonical form
    std::vector<std::string> algorithm_specs; // canonical, one per optimiser
    std::vector<std::string> problem_specs;   // canonical, ranges expanded
    std::vector<std::unique_ptr<Optimizer>> optimizers;
    std::vector<std::unique_ptr<Problem>> problems;
    // Union of the problems' parameter names, in order of first appearance (runs.csv columns).
    std::vector<std::string> parameter_columns;

    [[nodiscard]] std::int64_t run_count() const;
    // The request of run `run_id` in [0, run_count()); throws std::out_of_range otherwise.
    [[nodiscard]] RunRequest request(std::int64_t run_id) const;
};

// Validates `study` against the registries and builds its components. Every problem found is
// reported in one std::invalid_argument, one line each, naming the component, the parameter,
// the value and what is allowed (e.g. `random-search: parameter 'batch' = 0 is outside [1, 1e9]`).
PreparedStudy prepare_study(const Study& study, const AlgorithmRegistry& algorithms = builtin_algorithms(),
                            const ProblemRegistry& problems = builtin_problems());

} // namespace mhb
