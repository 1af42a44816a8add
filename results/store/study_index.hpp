// A finished study's runs of one budget grouped by (problem, algorithm), in the order they first
// appear in runs.csv, with the spec texts split into name and key=value parameters, each
// algorithm's display label and full spec (algorithms.csv), and whether each problem's runs are
// paired by seed. Everything the report computes starts from here. (results/ reads specs as text:
// it depends on no other library.)
//
// A study may hold several budgets (RunRecord::budget, a factor of its design): an index covers
// one of them, since runs at different budgets are different experiments.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "results/store/run_record.hpp"
#include "results/store/study_data.hpp"

namespace mhb {

// "name:key=value,key=value" split into its parts (no validation: the spec was valid when run).
struct SpecText {
    std::string name;
    std::map<std::string, std::string> parameters;
};
SpecText split_spec_text(const std::string& spec);
// The value of a numeric parameter of a spec, if present and numeric.
std::optional<double> spec_number(const SpecText& spec, const std::string& key);

// The distinct budgets of a study's runs, in the order they first appear (one "" for old studies;
// none for a study without runs).
std::vector<std::string> study_budgets(const StudyData& data);
// A file-name-safe form of a budget: "iterations=150,evaluations=2e4" -> "iterations_150_evaluations_2e4";
// "" -> "budget_unspecified".
std::string budget_slug(const std::string& budget);

struct RunGroup {
    std::string problem;
    std::string algorithm;
    std::vector<const RunRecord*> runs; // successful runs, by run index
    std::size_t failed = 0;

    [[nodiscard]] std::vector<double> final_values() const;
    // Every successful run knows f* (so the log10 gap is defined for each); false without runs.
    [[nodiscard]] bool optimum_known() const;
    // The successful run with this run index, or nullptr.
    [[nodiscard]] const RunRecord* run_with_index(std::int64_t run_index) const;
};

// A value `of` each run of two groups, on the run indices where both have a successful run, in
// run-index order: the pairs of a paired test. paired_final_values pairs the final values.
struct PairedValues {
    std::vector<double> x;
    std::vector<double> y;
};
PairedValues paired_values(const RunGroup& x, const RunGroup& y,
                           const std::function<double(const RunRecord&)>& of);
PairedValues paired_final_values(const RunGroup& x, const RunGroup& y);

class StudyIndex;
// One run of a report in a sentence: "sphere:dim=2, pso, run 3".
std::string run_name(const StudyIndex& index, const RunRecord& run);
// What every statistic left out or must warn about, for captions and the console, each a sentence
// (empty when there is nothing to say): "2 failed runs left out of every statistic (first: sphere,
// pso, run 3: the problem returned NaN at evaluation 12)." and "5 runs ended at +inf: ...".
std::string failed_runs_note(const StudyIndex& index);
std::string infinite_runs_note(const StudyIndex& index);
// Both notes, each after a space: what a caption appends.
std::string left_out_notes(const StudyIndex& index);

class StudyIndex {
public:
    // Indexes the runs of `budget`; without one, all runs, which must then share one budget
    // (std::logic_error otherwise: build one index per budget).
    explicit StudyIndex(const StudyData& data, const std::optional<std::string>& budget = std::nullopt);

    [[nodiscard]] const std::string& budget() const { return budget_; }
    [[nodiscard]] const std::vector<std::string>& problems() const { return problems_; }
    [[nodiscard]] const std::vector<std::string>& algorithms() const { return algorithms_; }
    // nullptr when the pair has no successful run.
    [[nodiscard]] const RunGroup* find(const std::string& problem, const std::string& algorithm) const;
    // The pair's group even when every run of it failed (runs empty, failed > 0); nullptr when the
    // pair never ran.
    [[nodiscard]] const RunGroup* group(const std::string& problem, const std::string& algorithm) const;
    // Algorithms with at least one successful run on the problem, in study order.
    [[nodiscard]] std::vector<std::string> algorithms_on(const std::string& problem) const;
    [[nodiscard]] const std::vector<RunGroup>& groups() const { return groups_; }
    [[nodiscard]] std::size_t failed_runs() const { return failed_; }
    // The failed runs (left out of every statistic), in run order.
    [[nodiscard]] const std::vector<const RunRecord*>& failed() const { return failed_records_; }
    // Successful runs whose final value is not finite (+inf: legal, the worst; -inf only where the
    // problem has no finite minimum).
    [[nodiscard]] std::size_t infinite_runs() const { return infinite_; }
    [[nodiscard]] std::size_t negative_infinite_runs() const { return negative_infinite_; }

    // The display label and the full spec (every parameter, defaults included) of an algorithm
    // spec, from algorithms.csv; the spec itself for studies without that file.
    [[nodiscard]] std::string label(const std::string& algorithm) const;
    [[nodiscard]] std::string full_spec(const std::string& algorithm) const;

    // Whether the runs on `problem` are paired by (problem, run index): at least two algorithms ran
    // on it and, for every run index, every algorithm's run (failed ones included) has the same
    // seed (common random numbers). With per-algorithm seeds they differ and runs are independent.
    [[nodiscard]] bool paired(const std::string& problem) const;

private:
    std::string budget_;
    std::vector<std::string> problems_;
    std::vector<std::string> algorithms_;
    std::vector<RunGroup> groups_;
    std::size_t failed_ = 0;
    std::vector<const RunRecord*> failed_records_;
    std::size_t infinite_ = 0;
    std::size_t negative_infinite_ = 0;
    std::map<std::string, std::string> labels_;
    std::map<std::string, std::string> full_specs_;
    std::map<std::string, bool> paired_;
};

} // namespace mhb
