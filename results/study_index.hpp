// A finished study's runs grouped by (problem, algorithm), in the order they first appear in
// runs.csv, with the spec texts split into name and key=value parameters. Everything the report
// computes starts from here. (results/ reads specs as text: it depends on no other library.)
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "results/run_record.hpp"
#include "results/store.hpp"

namespace mhb {

// "name:key=value,key=value" split into its parts (no validation: the spec was valid when run).
struct SpecText {
    std::string name;
    std::map<std::string, std::string> parameters;
};
SpecText split_spec_text(const std::string& spec);
// The value of a numeric parameter of a spec, if present and numeric.
std::optional<double> spec_number(const SpecText& spec, const std::string& key);

struct RunGroup {
    std::string problem;
    std::string algorithm;
    std::vector<const RunRecord*> runs; // successful runs, by run index
    std::size_t failed = 0;

    [[nodiscard]] std::vector<double> final_values() const;
};

class StudyIndex {
public:
    explicit StudyIndex(const StudyData& data);

    [[nodiscard]] const std::vector<std::string>& problems() const { return problems_; }
    [[nodiscard]] const std::vector<std::string>& algorithms() const { return algorithms_; }
    // nullptr when the pair has no successful run.
    [[nodiscard]] const RunGroup* find(const std::string& problem, const std::string& algorithm) const;
    // Algorithms with at least one successful run on the problem, in study order.
    [[nodiscard]] std::vector<std::string> algorithms_on(const std::string& problem) const;
    [[nodiscard]] const std::vector<RunGroup>& groups() const { return groups_; }
    [[nodiscard]] std::size_t failed_runs() const { return failed_; }

private:
    std::vector<std::string> problems_;
    std::vector<std::string> algorithms_;
    std::vector<RunGroup> groups_;
    std::size_t failed_ = 0;
};

} // namespace mhb
