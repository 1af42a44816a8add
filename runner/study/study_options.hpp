// The options that describe a study, declared once and shared by `mhbench run`'s command line
// and by study files (which use the same names: `algorithms = ...` in a file is
// `--algorithms ...` on the command line). Threads, the output directory and the report options
// are not among them: they do not change a study's results.
#pragma once

#include <boost/program_options/options_description.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "runner/study/study.hpp"

namespace mhb {

// algorithms/algorithm, problems/problem, runs, seed, seeds, iterations, evaluations, target,
// relative-target, budget/budgets, protocol, plugins/plugin, with their help texts.
boost::program_options::options_description study_options();

// Applies the study options of one source — the command line, or one study file — on top of a
// study. What a source gives replaces the study's value; a source's algorithm (problem) lines
// together replace the study's list. A source's iterations/evaluations make one budget and its
// budget lines one budget each; together they replace the study's budgets, and a target or a
// relative target applies to every budget (replacing the target it had, of either kind). Errors are
// collected, each prefixed with where the option was written.
class StudyOptionReader {
public:
    explicit StudyOptionReader(Study& study) : study_(study) {}

    // One option as written: `key` is an option's long name, `where` e.g. "ablation.ini:4" (empty
    // for the command line).
    void apply(const std::string& key, const std::string& value, const std::string& where,
               std::vector<std::string>& errors);
    // Call once after the last apply(): builds the source's budgets.
    void finish(std::vector<std::string>& errors);

private:
    void finish_precision(std::vector<std::string>& errors);

    Study& study_;
    std::set<std::string> seen_;
    std::optional<std::int64_t> iterations_;
    std::optional<std::int64_t> evaluations_;
    std::optional<DimensionEvaluations> evaluations_by_dimension_;
    std::optional<double> target_;
    std::optional<double> relative_target_;
    std::vector<StudyBudget> budgets_;
    // Runs by precision: applied in finish(), whatever order the keys came in.
    std::optional<double> precision_;
    std::optional<std::int64_t> max_runs_;
    std::optional<std::int64_t> initial_runs_;
    std::optional<std::int64_t> round_runs_;
};

} // namespace mhb
