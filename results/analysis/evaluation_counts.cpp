#include "results/analysis/evaluation_counts.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "results/analysis/dimension_budget.hpp"

namespace mhb {

namespace {

// A run's sampled points (iteration ends and checkpoints, then its final value) by evaluation count:
// all there is of runs stored before improvements were recorded.
std::vector<CheckpointSample> sampled_points(const RunRecord& r) {
    std::vector<CheckpointSample> points;
    for (const auto& p : r.curve)
        points.push_back({p.evaluations, p.best_f});
    for (const auto& c : r.checkpoints)
        points.push_back({c.evaluations, c.best_f});
    points.push_back({r.evaluations, r.best_f});
    std::stable_sort(points.begin(), points.end(),
                     [](const auto& a, const auto& b) { return a.evaluations < b.evaluations; });
    return points;
}

} // namespace

double value_at_evaluations(const RunRecord& r, std::int64_t at) {
    if (r.evaluations <= at)
        return r.best_f;
    if (at < 1)
        return NAN;
    if (r.improvements) {
        const auto& points = r.improvements->points;
        const auto after = std::upper_bound(points.begin(), points.end(), at,
                                            [](std::int64_t n, const auto& p) { return n < p.evaluations; });
        return after == points.begin() ? INFINITY : std::prev(after)->best_f;
    }
    double value = NAN;
    for (const auto& p : sampled_points(r))
        if (p.evaluations <= at)
            value = p.best_f;
    return value;
}

std::optional<std::int64_t> first_evaluation_reaching(const RunRecord& r,
                                                      const std::function<bool(double)>& reached) {
    if (r.improvements) {
        for (const auto& p : r.improvements->points)
            if (reached(p.best_f))
                return p.evaluations;
        return std::nullopt;
    }
    for (const auto& p : sampled_points(r))
        if (reached(p.best_f))
            return p.evaluations;
    return std::nullopt;
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
