#include "runner/study.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "problems/parameters.hpp"
#include "problems/spec.hpp"

namespace mhb {
namespace {

// An error message may hold several lines (validate_parameters joins all of a spec's problems);
// each becomes its own entry so the final report stays one line per problem.
void add_lines(std::vector<std::string>& errors, const std::string& text) {
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto end = std::min(text.find('\n', start), text.size());
        if (end > start)
            errors.push_back(text.substr(start, end - start));
        start = end + 1;
    }
}

void check_budget(const Budget& budget, std::vector<std::string>& errors) {
    if (!budget.max_evaluations && !budget.max_iterations)
        errors.emplace_back("budget: give a number of iterations or of evaluations (or both)");
    if (budget.max_iterations && *budget.max_iterations <= 0)
        errors.push_back("budget: iterations = " + std::to_string(*budget.max_iterations) +
                         " is outside [1, inf)");
    if (budget.max_evaluations && *budget.max_evaluations <= 0)
        errors.push_back("budget: evaluations = " + std::to_string(*budget.max_evaluations) +
                         " is outside [1, inf)");
    if (budget.target_error && !(std::isfinite(*budget.target_error) && *budget.target_error >= 0.0))
        errors.push_back("budget: target = " + format_real(*budget.target_error) + " is outside [0, inf)");
}

// Parses each spec, reporting errors with the kind of component ("algorithm", "problem").
std::vector<Spec> parse_specs(const std::vector<std::string>& texts, const char* kind,
                              std::vector<std::string>& errors) {
    std::vector<Spec> specs;
    if (texts.empty())
        errors.push_back(std::string("no ") + kind + " given");
    for (const auto& text : texts) {
        try {
            specs.push_back(Spec::parse(text));
        } catch (const std::invalid_argument& e) {
            errors.push_back(std::string(kind) + " " + e.what());
        }
    }
    return specs;
}

template <class Product>
std::unique_ptr<Product> create_checked(const Registry<Product>& registry, const Spec& spec,
                                        std::vector<std::string>& errors) {
    try {
        return registry.create(spec);
    } catch (const std::exception& e) {
        add_lines(errors, e.what());
        return nullptr;
    }
}

void reject_repeats(const std::vector<std::string>& canonical, const char* kind,
                    std::vector<std::string>& errors) {
    for (std::size_t i = 0; i < canonical.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (canonical[i] == canonical[j]) {
                // The same spec twice would repeat the same seeds: identical runs counted twice.
                errors.push_back(std::string(kind) + " '" + canonical[i] + "' is listed twice");
                break;
            }
}

} // namespace

std::int64_t PreparedStudy::run_count() const {
    return static_cast<std::int64_t>(problems.size() * optimizers.size()) * study.runs;
}

RunRequest PreparedStudy::request(std::int64_t run_id) const {
    if (run_id < 0 || run_id >= run_count())
        throw std::out_of_range("run_id " + std::to_string(run_id) + " is outside [0, " +
                                std::to_string(run_count()) + ")");
    const auto algorithm_count = static_cast<std::int64_t>(optimizers.size());
    const std::int64_t run_index = run_id % study.runs;
    const std::int64_t pair = run_id / study.runs;
    const auto a = static_cast<std::size_t>(pair % algorithm_count);
    const auto p = static_cast<std::size_t>(pair / algorithm_count);
    RunRequest r;
    r.optimizer = optimizers[a].get();
    r.problem = problems[p].get();
    r.algorithm_spec = algorithm_specs[a];
    r.problem_spec = problem_specs[p];
    r.run_id = run_id;
    r.run_index = run_index;
    r.study_seed = study.seed;
    r.budget = study.budget;
    return r;
}

PreparedStudy prepare_study(const Study& study, const AlgorithmRegistry& algorithms,
                            const ProblemRegistry& problems) {
    std::vector<std::string> errors;
    PreparedStudy prepared;
    prepared.study = study;
    prepared.study.algorithms.clear();
    prepared.study.problems.clear();

    for (const Spec& spec : parse_specs(study.algorithms, "algorithm", errors)) {
        prepared.study.algorithms.push_back(spec.canonical());
        prepared.algorithm_specs.push_back(spec.canonical());
        prepared.optimizers.push_back(create_checked(algorithms, spec, errors));
    }
    for (const Spec& spec : parse_specs(study.problems, "problem", errors)) {
        prepared.study.problems.push_back(spec.canonical());
        std::vector<Spec> expanded;
        try {
            // Canonical order first, so that `f=1-3,i=1-2` and `i=1-2,f=1-3` number runs alike.
            expanded = problems.expand(Spec::parse(spec.canonical()));
        } catch (const std::exception& e) {
            add_lines(errors, e.what());
            continue;
        }
        for (const Spec& one : expanded) {
            prepared.problem_specs.push_back(one.canonical());
            prepared.problems.push_back(create_checked(problems, one, errors));
        }
    }
    reject_repeats(prepared.algorithm_specs, "algorithm", errors);
    reject_repeats(prepared.problem_specs, "problem", errors);

    if (study.runs < 1 || study.runs > max_runs_per_pair)
        errors.push_back("study: runs = " + std::to_string(study.runs) + " is outside [1, " +
                         std::to_string(max_runs_per_pair) + "]");
    check_budget(study.budget, errors);
    if (study.budget.target_error)
        for (std::size_t p = 0; p < prepared.problems.size(); ++p)
            if (prepared.problems[p] && !prepared.problems[p]->known_optimum())
                errors.push_back("budget: a target needs a known optimum; problem '" +
                                 prepared.problem_specs[p] + "' has none");

    if (!errors.empty()) {
        std::string joined;
        for (const auto& e : errors)
            joined += (joined.empty() ? "" : "\n") + e;
        throw std::invalid_argument(joined);
    }

    for (const auto& problem : prepared.problems)
        for (const auto& name : problem->parameter_names())
            if (std::find(prepared.parameter_columns.begin(), prepared.parameter_columns.end(), name) ==
                prepared.parameter_columns.end())
                prepared.parameter_columns.push_back(name);
    return prepared;
}

} // namespace mhb
