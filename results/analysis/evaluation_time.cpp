#include "results/analysis/evaluation_time.hpp"

#include "results/analysis/evaluation_counts.hpp" // problem_dimension
#include "results/analysis/statistics.hpp"

namespace mhb {

std::vector<EvaluationTime> evaluation_times(const StudyIndex& index,
                                             const std::map<std::int64_t, double>& wall_seconds) {
    std::vector<EvaluationTime> times;
    if (wall_seconds.empty())
        return times;
    for (const auto& g : index.groups()) {
        std::vector<double> per_evaluation;
        EvaluationTime t{g.problem, g.algorithm, problem_dimension(index, g.problem), 0, 0.0, 0.0};
        for (const RunRecord* r : g.runs) {
            const auto wall = wall_seconds.find(r->run_id);
            if (wall == wall_seconds.end() || r->evaluations < 1)
                continue;
            per_evaluation.push_back(1e6 * wall->second / static_cast<double>(r->evaluations));
            t.total_seconds += wall->second;
        }
        if (per_evaluation.empty())
            continue;
        t.runs = per_evaluation.size();
        t.median_microseconds = median_of(std::move(per_evaluation));
        times.push_back(t);
    }
    return times;
}

} // namespace mhb
