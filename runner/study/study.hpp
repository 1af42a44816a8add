// A study: every algorithm spec x every problem spec x every budget x `runs` repetitions, with
// one study seed. This is what a user describes (on the command line, in a study file or through
// a preset); prepare_study() checks all of it at once, expands grids and ranges, and builds each
// optimiser and problem once, to be shared read-only by all their runs.
//
// Paths in `data=` are made absolute in `study.problems` (what study.ini stores), so a study
// file works from any directory; each PreparedProblem::spec keeps them as written.
//
// Run numbering is fixed: run_id = ((budget * problems + problem) * algorithms + algorithm) * runs
// + run index, in the order the specs are listed (grids and ranges expanded in place). Seeds come
// from (study seed, problem, run index) by default — common random numbers: run r on problem p
// starts from the same stream for every algorithm and every budget, so runs pair across them —
// or also from the algorithm (`seeds = per-algorithm`). Either way a study's results do not
// depend on how many threads execute it.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"
#include "results/analysis/run_precision.hpp"
#include "results/store/algorithm_info.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/prepared_components.hpp"
#include "runner/study/study_budget.hpp"

namespace mhb {

enum class SeedMode {
    common,        // seed from (study seed, problem, run index): every algorithm shares run r's stream
    per_algorithm, // seed from (study seed, algorithm, problem, run index)
};

// "common" or "per-algorithm", as written in study files and on the command line.
std::string_view seed_mode_name(SeedMode mode);

struct Study {
    // Specs as the user writes them: `pso:w=0.7`, grids `itlbo:tutorial={on,off}`, an algorithm's
    // display name `label=...`, integer ranges in problems `bbob:f=1-24`.
    std::vector<std::string> algorithms;
    std::vector<std::string> problems;
    // Where each spec was written (e.g. "ablation.ini:5"), prefixed to its errors; entries may be
    // missing or empty (then errors carry no prefix).
    std::vector<std::string> algorithm_origins;
    std::vector<std::string> problem_origins;
    std::int64_t runs = 20; // repetitions of each (algorithm, problem, budget); with by_precision, the most
    // Runs by precision (`runs = auto`): each cell gets the runs its rule asks for, up to `runs`
    // (= by_precision->max), in rounds (runner/execution/precision_rounds.hpp); none: `runs` each.
    std::optional<PrecisionRule> by_precision{};
    std::uint64_t seed = 1;
    SeedMode seeds = SeedMode::common;
    // Iterations and/or evaluations (whichever is spent first), optional target (absolute or
    // relative to f*); several budgets
    // make the budget a factor of the study, each reported separately.
    std::vector<StudyBudget> budgets{StudyBudget{}};
    // The protocol the study follows ("cec2017", "cec2022"; results/protocols/protocol_registry.hpp),
    // or empty. It changes no run: the protocol checks the study (a CEC protocol: problems of its
    // suite, budgets that give an evaluation count), and the report adds its tables and files. (Its
    // initializer spares aggregate initialisations that end before it a -Wmissing-field-initializers.)
    std::string protocol{};
    // Plug-in modules (runner/plugins/plugin_loader.hpp) whose components the study names, as absolute
    // paths; study.ini keeps them so that `--study-file DIR/study.ini` loads them again.
    std::vector<std::string> plugins{};
};

inline constexpr std::int64_t max_runs_per_pair = 1000000;

// A validated study, ready to run.
struct PreparedStudy {
    Study study;                               // grids expanded, specs canonical: what study files store
    std::vector<PreparedAlgorithm> algorithms; // in the order of the specs, grids expanded
    std::vector<PreparedProblem> problems;     // in the order of the specs, grids and ranges expanded
    std::vector<std::string> budget_texts;     // budget_text of each of study.budgets
    // Union of the problems' parameter names, in order of first appearance (runs.csv columns).
    std::vector<std::string> parameter_columns;

    [[nodiscard]] std::int64_t run_count() const;
    // The spec, label and full spec of each algorithm (algorithms.csv).
    [[nodiscard]] std::vector<AlgorithmInfo> algorithm_infos() const;
    // Which algorithm, problem and budget (indices into the vectors above) and which repetition
    // run `run_id` is, by the fixed numbering; throws std::out_of_range outside [0, run_count()).
    struct RunCell {
        std::size_t algorithm = 0;
        std::size_t problem = 0;
        std::size_t budget = 0;
        std::int64_t run_index = 0;
    };
    [[nodiscard]] RunCell cell(std::int64_t run_id) const;
    // The budget of a run of budget `budget` on problem `problem` (indices into study.budgets and
    // problems): its evaluations at the problem's dimension, its target resolved against the
    // problem's f* (StudyBudget::for_problem).
    [[nodiscard]] Budget budget_for(std::size_t budget, std::size_t problem) const;
    // The request of run `run_id` in [0, run_count()); throws std::out_of_range otherwise.
    [[nodiscard]] RunRequest request(std::int64_t run_id) const;
};

// Validates `study` against the registries and builds its components. Every problem found is
// reported in one std::invalid_argument, one line each, naming where the spec was written, the
// component, the parameter, the value and what is allowed (e.g. `ablation.ini:4: pso: parameter
// 'w' = 1.3 is outside [0, 1]`).
PreparedStudy prepare_study(const Study& study, const AlgorithmRegistry& algorithms = builtin_algorithms(),
                            const ProblemRegistry& problems = builtin_problems());

} // namespace mhb
