#include "runner/study/study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "problems/core/parameters.hpp"
#include "problems/core/rng.hpp"
#include "problems/core/spec.hpp"
#include "problems/core/spec_grid.hpp"
#include "results/protocols/protocol_registry.hpp"
#include "runner/study/algorithm_labels.hpp"

namespace mhb {
namespace {

// An error message may hold several lines (validate_parameters joins all of a spec's problems);
// each becomes its own entry, prefixed with where the spec was written.
void add_lines(std::vector<std::string>& errors, const std::string& origin, const std::string& text) {
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto end = std::min(text.find('\n', start), text.size());
        if (end > start)
            errors.push_back((origin.empty() ? "" : origin + ": ") + text.substr(start, end - start));
        start = end + 1;
    }
}

void check_budget(const StudyBudget& budget, std::vector<std::string>& errors) {
    if (!budget.max_evaluations && !budget.max_iterations && !budget.evaluations_by_dimension)
        errors.emplace_back("budget: give a number of iterations or of evaluations (or both)");
    if (budget.max_iterations && *budget.max_iterations <= 0)
        errors.push_back("budget: iterations = " + std::to_string(*budget.max_iterations) +
                         " is outside [1, inf)");
    if (budget.max_evaluations && *budget.max_evaluations <= 0)
        errors.push_back("budget: evaluations = " + std::to_string(*budget.max_evaluations) +
                         " is outside [1, inf)");
    if (budget.target_error && !(std::isfinite(*budget.target_error) && *budget.target_error >= 0.0))
        errors.push_back("budget: target = " + format_real(*budget.target_error) + " is outside [0, inf)");
    if (budget.relative_target && !(std::isfinite(*budget.relative_target) && *budget.relative_target >= 0.0))
        errors.push_back("budget: relative_target = " + format_real(*budget.relative_target) +
                         " is outside [0, inf)");
    if (budget.target_error && budget.relative_target)
        errors.push_back(
            "budget '" + budget_text(budget) +
            "': give target=E (f - f* <= E) or relative_target=R (f - f* <= R x |f*|), not both");
}

// A target needs f*, and a relative one a finite, non-zero f*: said once per problem, however many
// budgets set one.
void check_targets(const PreparedStudy& prepared, std::vector<std::string>& errors) {
    const auto& budgets = prepared.study.budgets;
    const bool absolute = std::any_of(budgets.begin(), budgets.end(),
                                      [](const StudyBudget& b) { return b.target_error.has_value(); });
    const bool relative = std::any_of(budgets.begin(), budgets.end(),
                                      [](const StudyBudget& b) { return b.relative_target.has_value(); });
    if (!absolute && !relative)
        return;
    for (const PreparedProblem& problem : prepared.problems) {
        if (!problem.problem)
            continue;
        const std::string& spec = problem.spec;
        const auto optimum = problem.problem->known_optimum();
        if (!optimum) {
            errors.push_back(std::string("budget: a ") + (relative && !absolute ? "relative " : "") +
                             "target needs a known optimum; problem '" + spec + "' has none");
            continue;
        }
        if (relative && relative_target_refusal(optimum->f))
            errors.push_back("budget: a relative target needs a finite, non-zero f* (it stops at f - f* <= "
                             "relative_target x |f*|); problem '" +
                             spec + "' has f* = " + format_real(optimum->f) + ": give target=E instead");
    }
}

std::string origin_of(const std::vector<std::string>& origins, std::size_t i) {
    return i < origins.size() ? origins[i] : std::string();
}

// `spec` with its display name attached, as study files store it.
std::string with_label(const std::string& spec, const std::string& label) {
    if (label == spec)
        return spec;
    return spec + (spec.find(':') == std::string::npos ? ":" : ",") + "label=" + label;
}

// The labels of the specs without `label=` that are not grid variants, decided together
// (algorithm_labels.hpp): canonical spec -> label. Specs with errors are left to prepare_algorithms.
std::map<std::string, std::string> default_labels(const Study& study, const AlgorithmRegistry& registry) {
    std::map<std::string, std::string> wanted;
    std::vector<std::string> taken;
    for (const auto& text : study.algorithms) {
        try {
            const std::vector<GridVariant> variants = expand_grid(text);
            for (const auto& variant : variants) {
                const Spec spec = Spec::parse(variant.text);
                if (const std::string* given = spec.find("label"))
                    taken.push_back(*given);
                else if (!variant.varying.empty())
                    taken.push_back(grid_label(registry.find(spec.name), variant.varying));
                else
                    wanted[registry.minimal(spec).canonical()] = short_label(registry, spec);
            }
        } catch (const std::exception&) {
        }
    }
    return unique_short_labels(wanted, taken);
}

// Expands the algorithm specs (grids, labels), validates and builds each optimiser.
void prepare_algorithms(const Study& study, const AlgorithmRegistry& registry, PreparedStudy& prepared,
                        std::vector<std::string>& errors) {
    if (study.algorithms.empty())
        errors.emplace_back("no algorithm given");
    std::map<std::string, std::string> where_spec;  // canonical spec -> the text that gave it
    std::map<std::string, std::string> where_label; // label -> canonical spec
    const std::map<std::string, std::string> short_labels = default_labels(study, registry);
    for (std::size_t i = 0; i < study.algorithms.size(); ++i) {
        const std::string origin = origin_of(study.algorithm_origins, i);
        std::vector<GridVariant> variants;
        try {
            variants = expand_grid(study.algorithms[i]);
        } catch (const std::invalid_argument& e) {
            add_lines(errors, origin, std::string("algorithm ") + e.what());
            continue;
        }
        for (const auto& variant : variants) {
            Spec spec;
            try {
                spec = Spec::parse(variant.text);
            } catch (const std::invalid_argument& e) {
                add_lines(errors, origin, std::string("algorithm ") + e.what());
                continue;
            }
            try {
                std::string label;
                if (const std::string* given = spec.find("label")) {
                    label = *given;
                    std::erase_if(spec.parameters, [](const auto& kv) { return kv.first == "label"; });
                    if (variants.size() > 1) {
                        add_lines(errors, origin,
                                  spec.name + ": label '" + label + "' would name all " +
                                      std::to_string(variants.size()) +
                                      " variants of the grid; leave it out (each variant gets a label of its "
                                      "own) or write the variants one by one");
                        break;
                    }
                }
                const AlgorithmRegistry::Entry& entry = registry.find(spec.name);
                const std::string canonical = registry.minimal(spec).canonical();
                // A short label is derived again whenever the study is prepared, so study.ini keeps
                // the canonical spec alone; given and grid labels are written into it.
                const bool short_label_used = label.empty() && variant.varying.empty();
                if (short_label_used)
                    label = short_labels.count(canonical) != 0 ? short_labels.at(canonical) : canonical;
                else if (label.empty())
                    label = grid_label(entry, variant.varying);
                if (const auto seen = where_spec.find(canonical); seen != where_spec.end()) {
                    // The same optimiser twice would repeat the same runs, counted twice.
                    errors.push_back((origin.empty() ? "" : origin + ": ") + "algorithm '" + variant.text +
                                     "' is the same optimiser as '" + seen->second + "' (both are '" +
                                     canonical + "')");
                    continue;
                }
                if (const auto seen = where_label.find(label); seen != where_label.end()) {
                    errors.push_back((origin.empty() ? "" : origin + ": ") + "algorithm label '" + label +
                                     "' names both '" + seen->second + "' and '" + canonical + "'");
                    continue;
                }
                where_spec[canonical] = variant.text;
                where_label[label] = canonical;
                PreparedAlgorithm algorithm;
                algorithm.optimizer = registry.create(spec);
                algorithm.info = {canonical, label, registry.full(spec).canonical()};
                algorithm.version = entry.version;
                algorithm.module = {entry.module_path, entry.module_sha256};
                prepared.algorithms.push_back(std::move(algorithm));
                prepared.study.algorithms.push_back(short_label_used ? canonical
                                                                     : with_label(canonical, label));
            } catch (const std::exception& e) {
                add_lines(errors, origin, e.what());
            }
        }
    }
}

// `spec` with a relative `data=` path made absolute, so that a study file written into the study
// directory reads the same data from wherever it is used. Paths joined by '+' are each resolved.
Spec with_absolute_data_paths(Spec spec) {
    for (auto& [key, value] : spec.parameters) {
        if (key != "data")
            continue;
        std::string joined;
        std::size_t start = 0;
        while (start <= value.size()) {
            const auto end = std::min(value.find('+', start), value.size());
            std::filesystem::path path = value.substr(start, end - start);
            if (!path.empty() && path.is_relative())
                path = std::filesystem::absolute(path).lexically_normal();
            if (!joined.empty())
                joined += '+';
            joined += path.string();
            start = end + 1;
        }
        value = joined;
    }
    return spec;
}

// The canonical spec with each data file named by its content ("data=sha256:..."), not its path:
// what a problem's runs depend on.
std::string content_identity(Spec spec, const std::vector<DataFile>& files) {
    if (files.empty())
        return spec.canonical();
    std::string hashes;
    for (const auto& file : files)
        hashes.append(hashes.empty() ? "sha256:" : "+sha256:").append(file.sha256);
    // Not a structured binding: clang-tidy 14 would not see the assignment through one.
    for (auto& parameter : spec.parameters)
        if (parameter.first == "data")
            parameter.second = hashes;
    return spec.canonical();
}

// Expands the problem specs (grids, then ranges), validates and builds each problem.
void prepare_problems(const Study& study, const ProblemRegistry& registry, PreparedStudy& prepared,
                      std::vector<std::string>& errors) {
    if (study.problems.empty())
        errors.emplace_back("no problem given");
    std::map<std::string, std::string> where_full; // full spec -> canonical spec that gave it
    for (std::size_t i = 0; i < study.problems.size(); ++i) {
        const std::string origin = origin_of(study.problem_origins, i);
        std::vector<GridVariant> variants;
        try {
            variants = expand_grid(study.problems[i]);
        } catch (const std::invalid_argument& e) {
            add_lines(errors, origin, std::string("problem ") + e.what());
            continue;
        }
        for (const auto& variant : variants) {
            Spec written;
            try {
                written = Spec::parse(variant.text);
            } catch (const std::invalid_argument& e) {
                add_lines(errors, origin, std::string("problem ") + e.what());
                continue;
            }
            prepared.study.problems.push_back(with_absolute_data_paths(written).canonical());
            std::vector<Spec> expanded;
            try {
                // Canonical order first, so that `f=1-3,i=1-2` and `i=1-2,f=1-3` number runs alike.
                expanded = registry.expand(Spec::parse(written.canonical()));
            } catch (const std::exception& e) {
                add_lines(errors, origin, e.what());
                continue;
            }
            for (const Spec& one : expanded) {
                try {
                    const std::string canonical = registry.normalised(one).canonical();
                    const std::string full = registry.full(one).canonical();
                    if (const auto seen = where_full.find(full); seen != where_full.end()) {
                        errors.push_back((origin.empty() ? "" : origin + ": ") + "problem '" + canonical +
                                         "' is the same problem as '" + seen->second + "'");
                        continue;
                    }
                    where_full[full] = canonical;
                    PreparedProblem problem;
                    problem.problem = registry.create(one);
                    problem.spec = canonical;
                    const ProblemRegistry::Entry& entry = registry.find(one.name);
                    problem.version = entry.version;
                    problem.module = {entry.module_path, entry.module_sha256};
                    problem.identity =
                        content_identity(Spec::parse(canonical), problem.problem->data_files());
                    prepared.problems.push_back(std::move(problem));
                } catch (const std::exception& e) {
                    add_lines(errors, origin, e.what());
                }
            }
        }
    }
}

// Evaluations by dimension must list every problem's dimension: said once per budget and dimension.
void check_dimension_budgets(const PreparedStudy& prepared, std::vector<std::string>& errors) {
    for (const StudyBudget& budget : prepared.study.budgets) {
        if (!budget.evaluations_by_dimension)
            continue;
        std::map<std::int64_t, std::pair<std::string, std::size_t>> missing; // D -> first problem, count
        std::set<std::int64_t> too_many; // N x D beyond the most a budget may give, said once per D
        for (const PreparedProblem& problem : prepared.problems) {
            const std::int64_t dimension = problem.problem->dimension();
            try {
                if (budget.evaluations_by_dimension->at(dimension))
                    continue;
            } catch (const std::invalid_argument& e) {
                if (too_many.insert(dimension).second)
                    errors.emplace_back(e.what());
                continue;
            }
            auto& [first, count] = missing[dimension];
            if (count++ == 0)
                first = problem.spec;
        }
        for (const auto& [dimension, first_and_count] : missing)
            errors.push_back("budget '" + budget_text(budget) + "' gives no evaluations at dimension " +
                             std::to_string(dimension) + " (problem '" + first_and_count.first + "'" +
                             (first_and_count.second > 1
                                  ? " and " + std::to_string(first_and_count.second - 1) + " more"
                                  : std::string()) +
                             "); it lists " + budget.evaluations_by_dimension->dimensions_text());
    }
}

// Every optimiser against every dimension of the study's problems (Optimizer::refusal): a
// population too small for the method or too large for memory is refused now, in one line per
// optimiser and dimension, rather than as a failure of each of its runs.
void check_optimizer_dimensions(const PreparedStudy& prepared, std::vector<std::string>& errors) {
    std::set<Eigen::Index> dimensions;
    for (const PreparedProblem& problem : prepared.problems)
        if (problem.problem)
            dimensions.insert(problem.problem->dimension());
    for (const PreparedAlgorithm& algorithm : prepared.algorithms)
        for (const Eigen::Index dimension : dimensions)
            if (auto refusal = algorithm.optimizer->refusal(dimension);
                refusal && std::find(errors.begin(), errors.end(), *refusal) == errors.end())
                errors.push_back(std::move(*refusal));
}

// The protocols in force (the one the study names, and those in force unnamed) check the study:
// a CEC protocol wants its suite's problems and budgets that give evaluation counts.
void check_protocol(const PreparedStudy& prepared, std::vector<std::string>& errors) {
    const std::string& name = prepared.study.protocol;
    if (!name.empty() && find_protocol(name) == nullptr) {
        errors.push_back("protocol = " + name + " is not one of " + protocol_names());
        return;
    }
    ProtocolStudy study;
    for (const PreparedProblem& problem : prepared.problems)
        study.problems.push_back({problem.spec, Spec::parse(problem.spec).name});
    for (const StudyBudget& budget : prepared.study.budgets)
        study.budgets.push_back(
            {budget_text(budget), budget.max_evaluations || budget.evaluations_by_dimension});
    for (const SuiteProtocol* protocol : protocols_in_force(name))
        protocol->check_study(study, errors);
}

} // namespace

std::string_view seed_mode_name(SeedMode mode) {
    return mode == SeedMode::common ? "common" : "per-algorithm";
}

std::int64_t PreparedStudy::run_count() const {
    return static_cast<std::int64_t>(problems.size() * algorithms.size() * study.budgets.size()) * study.runs;
}

std::vector<AlgorithmInfo> PreparedStudy::algorithm_infos() const {
    std::vector<AlgorithmInfo> infos;
    infos.reserve(algorithms.size());
    for (const PreparedAlgorithm& algorithm : algorithms)
        infos.push_back(algorithm.info);
    return infos;
}

PreparedStudy::RunCell PreparedStudy::cell(std::int64_t run_id) const {
    if (run_id < 0 || run_id >= run_count())
        throw std::out_of_range("run_id " + std::to_string(run_id) + " is outside [0, " +
                                std::to_string(run_count()) + ")");
    const auto algorithm_count = static_cast<std::int64_t>(algorithms.size());
    const auto problem_count = static_cast<std::int64_t>(problems.size());
    const std::int64_t pair = run_id / study.runs; // (budget * problems + problem) * algorithms + algorithm
    RunCell c;
    c.algorithm = static_cast<std::size_t>(pair % algorithm_count);
    c.problem = static_cast<std::size_t>((pair / algorithm_count) % problem_count);
    c.budget = static_cast<std::size_t>(pair / algorithm_count / problem_count);
    c.run_index = run_id % study.runs;
    return c;
}

Budget PreparedStudy::budget_for(std::size_t budget, std::size_t problem) const {
    const StudyBudget& b = study.budgets.at(budget);
    const Problem& p = *problems.at(problem).problem;
    // f* is asked for only where a target is relative to it (an output-error f* costs a simulation).
    std::optional<double> f_opt;
    if (b.relative_target)
        if (const auto optimum = p.known_optimum())
            f_opt = optimum->f;
    return b.for_problem(p.dimension(), f_opt);
}

RunRequest PreparedStudy::request(std::int64_t run_id) const {
    const RunCell c = cell(run_id);
    const PreparedAlgorithm& algorithm = algorithms[c.algorithm];
    const PreparedProblem& problem = problems[c.problem];
    RunRequest r;
    r.optimizer = algorithm.optimizer.get();
    r.problem = problem.problem.get();
    r.algorithm_spec = algorithm.info.spec;
    r.problem_spec = problem.spec;
    r.run_id = run_id;
    r.run_index = c.run_index;
    const auto index = static_cast<std::uint64_t>(c.run_index);
    r.seed = study.seeds == SeedMode::common
                 ? derive_seed(study.seed, problem.identity, index)
                 : derive_seed(study.seed, algorithm.info.spec, problem.identity, index);
    r.budget = budget_for(c.budget, c.problem);
    r.budget_text = budget_texts[c.budget];
    return r;
}

namespace {

// Runs by precision need a precision, and rounds that fit under the most runs.
void check_precision_rule(const PrecisionRule& rule, std::vector<std::string>& errors) {
    if (!(rule.precision > 0))
        errors.emplace_back("runs = auto needs precision = the standard error to reach on log10(f - f*), "
                            "e.g. --precision 0.05");
    if (rule.max < 2)
        errors.push_back("max-runs = " + std::to_string(rule.max) + " is outside [2, " +
                         std::to_string(max_runs_per_pair) + "]: a standard error needs two runs");
    else if (rule.initial < 2 || rule.initial > rule.max)
        errors.push_back("initial-runs = " + std::to_string(rule.initial) +
                         " is outside [2, max-runs = " + std::to_string(rule.max) + "]");
    if (rule.step < 1 || rule.step > rule.max)
        errors.push_back("round-runs = " + std::to_string(rule.step) +
                         " is outside [1, max-runs = " + std::to_string(rule.max) + "]");
}

} // namespace

PreparedStudy prepare_study(const Study& study, const AlgorithmRegistry& algorithms,
                            const ProblemRegistry& problems) {
    std::vector<std::string> errors;
    PreparedStudy prepared;
    prepared.study = study;
    prepared.study.algorithms.clear();
    prepared.study.problems.clear();
    prepared.study.algorithm_origins.clear();
    prepared.study.problem_origins.clear();

    prepare_algorithms(study, algorithms, prepared, errors);
    prepare_problems(study, problems, prepared, errors);

    if (study.runs < 1 || study.runs > max_runs_per_pair)
        errors.push_back("study: " + std::string(study.by_precision ? "max-runs" : "runs") + " = " +
                         std::to_string(study.runs) + " is outside [1, " + std::to_string(max_runs_per_pair) +
                         "]");
    if (study.by_precision)
        check_precision_rule(*study.by_precision, errors);
    if (study.budgets.empty())
        errors.emplace_back("budget: give a number of iterations or of evaluations (or both)");
    for (const StudyBudget& budget : study.budgets) {
        check_budget(budget, errors);
        const std::string text = budget_text(budget);
        if (std::find(prepared.budget_texts.begin(), prepared.budget_texts.end(), text) !=
            prepared.budget_texts.end())
            errors.push_back("budget '" + text + "' is listed twice");
        prepared.budget_texts.push_back(text);
    }
    check_dimension_budgets(prepared, errors);
    check_optimizer_dimensions(prepared, errors);
    check_protocol(prepared, errors);
    check_targets(prepared, errors);
    if (!errors.empty()) {
        std::string joined;
        for (const auto& e : errors)
            joined += (joined.empty() ? "" : "\n") + e;
        throw std::invalid_argument(joined);
    }

    for (const PreparedProblem& problem : prepared.problems)
        for (const auto& name : problem.problem->parameter_names())
            if (std::find(prepared.parameter_columns.begin(), prepared.parameter_columns.end(), name) ==
                prepared.parameter_columns.end())
                prepared.parameter_columns.push_back(name);
    return prepared;
}

} // namespace mhb
