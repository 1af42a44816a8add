#include "runner/study/calibration.hpp"

#include <algorithm>
#include <chrono>

#include "runner/run/execute_run.hpp"

namespace mhb {

double StudyEstimate::evaluations() const {
    double total = 0;
    for (const auto& b : budgets)
        total += b.evaluations;
    return total;
}

double StudyEstimate::cpu_seconds() const {
    double total = 0;
    for (const auto& b : budgets)
        total += b.cpu_seconds;
    return total;
}

RunRecord short_run(RunRequest request, std::int64_t max_evaluations) {
    request.budget.max_iterations = std::min<std::int64_t>(request.budget.max_iterations.value_or(3), 3);
    request.budget.max_evaluations =
        std::min<std::int64_t>(request.budget.max_evaluations.value_or(max_evaluations), max_evaluations);
    request.budget.target_error.reset();
    return execute_run(request);
}

double extrapolated_evaluations(const RunRecord& short_run, const Budget& budget) {
    // Evaluations of the initialisation (iteration 0) and per iteration after it.
    const double initial =
        short_run.curve.empty() ? 0.0 : static_cast<double>(short_run.curve.front().evaluations);
    const double per_iteration = short_run.iterations > 0
                                     ? (static_cast<double>(short_run.evaluations) - initial) /
                                           static_cast<double>(short_run.iterations)
                                     : static_cast<double>(short_run.evaluations);
    double full = budget.max_evaluations ? static_cast<double>(*budget.max_evaluations) : 1e300;
    if (budget.max_iterations)
        full = std::min(full, initial + per_iteration * static_cast<double>(*budget.max_iterations));
    return full;
}

StudyEstimate estimate_study(const PreparedStudy& study, std::size_t problems_per_algorithm) {
    StudyEstimate estimate;
    const std::size_t algorithms = study.optimizers.size();
    const std::size_t problems = study.problems.size();
    const std::size_t budgets = study.study.budgets.size();
    const double runs = static_cast<double>(study.study.runs);
    // Problems spread evenly over the list (first and last included), each used once.
    std::vector<std::size_t> sample;
    const std::size_t count = std::min(problems, std::max<std::size_t>(problems_per_algorithm, 1));
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t p = count == 1 ? 0 : i * (problems - 1) / (count - 1);
        if (sample.empty() || sample.back() != p)
            sample.push_back(p);
    }
    estimate.budgets.resize(budgets);
    for (std::size_t b = 0; b < budgets; ++b) {
        const StudyBudget& budget = study.study.budgets[b];
        BudgetEstimate& out = estimate.budgets[b];
        out.exact = (budget.max_evaluations || budget.evaluations_by_dimension) && !budget.max_iterations &&
                    !budget.target_error;
        for (std::size_t a = 0; a < algorithms; ++a) {
            double evaluations = 0; // per run, averaged over the sampled problems
            double seconds = 0;
            for (const std::size_t p : sample) {
                const auto run_id =
                    static_cast<std::int64_t>(((b * problems + p) * algorithms + a)) * study.study.runs;
                const RunRequest request = study.request(run_id);
                const auto started = std::chrono::steady_clock::now();
                const RunRecord record = short_run(request, 2000);
                const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;
                ++estimate.calibration_runs;
                if (!record.ok || record.evaluations <= 0)
                    continue;
                const double full = extrapolated_evaluations(record, request.budget); // at its dimension
                evaluations += full;
                seconds += full * wall.count() / static_cast<double>(record.evaluations);
            }
            const double share = static_cast<double>(problems) / static_cast<double>(sample.size());
            out.evaluations += evaluations * share * runs;
            out.cpu_seconds += seconds * share * runs;
        }
        if (out.exact) { // every run spends its budget: the count, not a sample's
            out.evaluations = 0;
            for (const auto& problem : study.problems)
                out.evaluations +=
                    static_cast<double>(*budget.for_dimension(problem->dimension()).max_evaluations) *
                    static_cast<double>(algorithms) * runs;
        }
    }
    return estimate;
}

} // namespace mhb
