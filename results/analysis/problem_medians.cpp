#include "results/analysis/problem_medians.hpp"

#include "results/analysis/statistics.hpp"

namespace mhb {

std::optional<std::pair<std::vector<std::string>, std::vector<std::vector<double>>>>
per_problem_medians(const StudyIndex& index) {
    // Problems on which every algorithm has runs: the blocks of the Friedman test.
    std::vector<std::string> problems;
    for (const auto& p : index.problems())
        if (index.algorithms_on(p).size() == index.algorithms().size())
            problems.push_back(p);
    if (problems.size() < 2 || index.algorithms().size() < 2)
        return std::nullopt;
    std::vector<std::vector<double>> medians;
    for (const auto& p : problems) {
        std::vector<double> row;
        for (const auto& a : index.algorithms())
            row.push_back(summarize(index.find(p, a)->final_values()).median);
        medians.push_back(row);
    }
    return std::make_pair(problems, medians);
}

} // namespace mhb
