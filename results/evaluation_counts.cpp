#include "results/evaluation_counts.hpp"

#include <algorithm>
#include <cmath>

#include "results/dimension_budget.hpp"

namespace mhb {

double value_at_evaluations(const RunRecord& r, std::int64_t at) {
    if (r.evaluations <= at)
        return r.best_f;
    double value = NAN;
    if (r.improvements) {
        for (const auto& p : r.improvements->points)
            if (p.evaluations <= at)
                value = p.best_f;
        return value;
    }
    std::int64_t best_evaluations = -1;
    const auto consider = [&](std::int64_t evaluations, double f) {
        if (evaluations <= at && evaluations >= best_evaluations) {
            best_evaluations = evaluations;
            value = f;
        }
    };
    for (const auto& p : r.curve)
        consider(p.evaluations, p.best_f);
    for (const auto& c : r.checkpoints)
        consider(c.evaluations, c.best_f);
    return value;
}

std::int64_t problem_dimension(const StudyIndex& index, const std::string& problem) {
    for (const auto& a : index.algorithms_on(problem))
        for (const auto* r : index.find(problem, a)->runs)
            if (!r->best_x.empty())
                return static_cast<std::int64_t>(r->best_x.size());
    return 0;
}

std::int64_t budget_evaluations(const StudyIndex& index, const std::string& problem) {
    if (const auto e = budget_evaluations_at(index.budget(), problem_dimension(index, problem)))
        return *e;
    std::int64_t most = 0;
    for (const auto& a : index.algorithms_on(problem))
        for (const auto* r : index.find(problem, a)->runs)
            most = std::max(most, r->evaluations);
    return most;
}

std::int64_t evaluations_at(double fraction, std::int64_t budget) {
    return static_cast<std::int64_t>(std::floor(fraction * static_cast<double>(budget) + 1e-9));
}

} // namespace mhb
