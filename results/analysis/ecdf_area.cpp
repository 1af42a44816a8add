#include "results/analysis/ecdf_area.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "results/analysis/curve_data.hpp" // ecdf_target_gaps: the figure's targets
#include "results/analysis/evaluation_counts.hpp"

namespace mhb {

double ecdf_area(const std::vector<std::optional<std::int64_t>>& first_hits, std::int64_t budget) {
    if (first_hits.empty() || budget < 1)
        throw std::invalid_argument("ecdf_area: needs at least one (run, target) pair and a budget >= 1");
    const double log_budget = std::log10(static_cast<double>(budget));
    double sum = 0.0;
    for (const auto& hit : first_hits) {
        if (!hit || *hit > budget)
            continue;
        // The ECDF steps up by one pair at log10(t) and stays up to log10(B).
        sum +=
            log_budget > 0.0
                ? (log_budget - std::log10(static_cast<double>(std::max<std::int64_t>(*hit, 1)))) / log_budget
                : 1.0;
    }
    return sum / static_cast<double>(first_hits.size());
}

namespace {

// The first hits of every (run, target) pair of a group, in run order then target order.
std::vector<std::optional<std::int64_t>> group_first_hits(const RunGroup& g) {
    std::vector<std::optional<std::int64_t>> hits;
    for (const RunRecord* r : g.runs) {
        const double f_opt = *r->f_opt;
        for (const double gap : ecdf_target_gaps())
            hits.push_back(first_evaluation_reaching(*r, [&](double f) { return f - f_opt <= gap; }));
    }
    return hits;
}

EcdfAreaCell area_cell(const RunGroup& g, std::int64_t budget) {
    const auto hits = group_first_hits(g);
    EcdfAreaCell cell{g.algorithm, g.runs.size(), hits.size(), 0, ecdf_area(hits, budget)};
    for (const auto& h : hits)
        cell.reached += h && *h <= budget ? 1U : 0U;
    return cell;
}

// Per algorithm, the mean of its areas over the problems it has one on.
EcdfAreaGroup pooled_group(const StudyIndex& index, const std::vector<EcdfAreaGroup>& per_problem) {
    EcdfAreaGroup pooled;
    pooled.problems = per_problem.size();
    for (const auto& a : index.algorithms()) {
        EcdfAreaCell cell{a, 0, 0, 0, 0.0};
        std::size_t problems = 0;
        for (const auto& group : per_problem)
            for (const auto& c : group.cells)
                if (c.algorithm == a) {
                    cell.runs += c.runs;
                    cell.pairs += c.pairs;
                    cell.reached += c.reached;
                    cell.area += c.area;
                    ++problems;
                }
        if (problems == 0)
            continue;
        cell.area /= static_cast<double>(problems);
        pooled.cells.push_back(cell);
    }
    return pooled;
}

} // namespace

std::vector<EcdfAreaGroup> ecdf_areas(const StudyIndex& index) {
    std::vector<EcdfAreaGroup> groups;
    for (const auto& problem : index.problems()) {
        EcdfAreaGroup group{problem, budget_evaluations(index, problem), 1, {}};
        if (group.budget < 1) // no run on it spent an evaluation
            continue;
        for (const auto& a : index.algorithms_on(problem))
            if (const RunGroup* g = index.find(problem, a); g != nullptr && g->optimum_known())
                group.cells.push_back(area_cell(*g, group.budget));
        if (!group.cells.empty())
            groups.push_back(std::move(group));
    }
    if (groups.size() >= 2)
        groups.push_back(pooled_group(index, groups));
    return groups;
}

} // namespace mhb
