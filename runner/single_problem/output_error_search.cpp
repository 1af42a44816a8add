#include "runner/single_problem/output_error_search.hpp"

#include <algorithm>
#include <memory>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/rng.hpp"
#include "problems/core/spec.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/study_budget.hpp"

namespace mhb {

pmsm::OutputIdentification identify_output_error(const pmsm::OutputErrorProblem& problem,
                                                 const OutputIdentificationOptions& options) {
    const Spec spec = Spec::parse(options.algorithm);
    const std::unique_ptr<Optimizer> optimizer = builtin_algorithms().create(spec);
    const std::string algorithm = builtin_algorithms().normalised(spec).canonical();
    const auto seeds = static_cast<std::size_t>(std::max(1, options.seeds));
    std::vector<RunRecord> records(seeds);
    std::optional<tbb::global_control> limit;
    if (options.threads > 0)
        limit.emplace(tbb::global_control::max_allowed_parallelism,
                      static_cast<std::size_t>(options.threads));
    tbb::parallel_for(std::size_t{0}, seeds, [&](std::size_t i) {
        RunRequest request;
        request.optimizer = optimizer.get();
        request.problem = &problem;
        request.algorithm_spec = algorithm;
        request.problem_spec = "pmsm:model=output";
        request.run_id = static_cast<std::int64_t>(i);
        request.run_index = static_cast<std::int64_t>(i);
        request.seed = derive_seed(options.seed, "identify output error", i);
        request.budget.max_evaluations = options.evaluations;
        request.budget_text = budget_text(request.budget);
        records[i] = execute_run(request);
    });

    const Eigen::Index k = problem.dimension();
    std::vector<Eigen::VectorXd> seed_x;
    std::vector<double> seed_f;
    for (const RunRecord& r : records) {
        if (!r.ok || r.best_x.size() != static_cast<std::size_t>(k))
            continue;
        seed_x.push_back(Eigen::Map<const Eigen::VectorXd>(r.best_x.data(), k));
        seed_f.push_back(r.best_f);
    }
    if (seed_x.empty())
        throw std::runtime_error("every run of " + algorithm + " failed" +
                                 (records.empty() ? std::string() : ": " + records.front().message));
    return pmsm::summarise_seeds(problem, std::move(seed_x), std::move(seed_f));
}

} // namespace mhb
