#include "runner/single_problem/output_error_identification.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <optional>
#include <stdexcept>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/rng.hpp"
#include "problems/core/spec.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/study.hpp"

namespace mhb {
namespace {

// The residuals r(theta) linearised at theta0 as the linear model b - A theta = r(theta0) + J
// (theta - theta0), J by central differences with steps of 1e-6 of each coordinate's box width.
pmsm::LinearModel linearise(const pmsm::OutputErrorProblem& problem, const Eigen::VectorXd& theta0) {
    const pmsm::OutputErrorModel& model = problem.model();
    const Eigen::Index k = theta0.size();
    Eigen::VectorXd r0, plus, minus;
    model.residuals(theta0, r0);
    Eigen::MatrixXd J(r0.size(), k);
    for (Eigen::Index j = 0; j < k; ++j) {
        const double h = 1e-6 * (problem.bounds().upper[j] - problem.bounds().lower[j]);
        Eigen::VectorXd x = theta0;
        x[j] = theta0[j] + h;
        model.residuals(x, plus);
        x[j] = theta0[j] - h;
        model.residuals(x, minus);
        J.col(j) = (plus - minus) / (2.0 * h);
    }
    pmsm::LinearModel out;
    out.A = -J;
    out.b = r0 - J * theta0;
    out.parameter_names = model.parameter_names();
    out.d_rows = model.rows();
    return out;
}

} // namespace

OutputIdentification identify_output_error(const pmsm::OutputErrorProblem& problem,
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

    OutputIdentification out;
    const Eigen::Index k = problem.dimension();
    for (const RunRecord& r : records) {
        if (!r.ok || r.best_x.size() != static_cast<std::size_t>(k))
            continue;
        out.seed_x.push_back(Eigen::Map<const Eigen::VectorXd>(r.best_x.data(), k));
        out.seed_f.push_back(r.best_f);
    }
    if (out.seed_x.empty())
        throw std::runtime_error("every run of " + algorithm + " failed" +
                                 (records.empty() ? std::string() : ": " + records.front().message));
    const auto best =
        static_cast<std::size_t>(std::min_element(out.seed_f.begin(), out.seed_f.end()) - out.seed_f.begin());
    out.best_x = out.seed_x[best];
    out.best_f = out.seed_f[best];
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(k);
    for (const auto& x : out.seed_x)
        mean += x;
    mean /= static_cast<double>(out.seed_x.size());
    out.spread = Eigen::VectorXd::Zero(k);
    for (const auto& x : out.seed_x)
        out.spread += (x - mean).cwiseAbs2();
    out.spread =
        (out.spread / std::max<double>(1.0, static_cast<double>(out.seed_x.size()) - 1.0)).cwiseSqrt();
    for (const double f : out.seed_f)
        out.seeds_at_best += f <= out.best_f + 1e-6 * std::fabs(out.best_f) ? 1 : 0;
    out.linearised = linearise(problem, out.best_x);
    return out;
}

} // namespace mhb
