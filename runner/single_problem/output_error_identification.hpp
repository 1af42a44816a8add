// The output-error identification of `mhbench identify --model output`: the model has no
// closed-form optimum, so a chosen optimiser (by default CMA-ES with IPOP restarts) is run from
// several seeds in parallel, the best point found is the estimate, and the spread of the seeds'
// answers is one error estimate; the residuals linearised at the estimate (a finite-difference
// Jacobian) give the other, with the same verdicts as the linear models.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "problems/pmsm/linear_model.hpp"
#include "problems/pmsm/output_error_problem.hpp"

namespace mhb {

struct OutputIdentificationOptions {
    std::string algorithm = "cmaes"; // a spec of the algorithm registry
    int seeds = 8;
    std::int64_t evaluations = 20000; // per seed
    std::uint64_t seed = 1;
    int threads = 0; // 0: all cores
};

struct OutputIdentification {
    Eigen::VectorXd best_x; // the best point of all seeds
    double best_f = 0.0;
    std::vector<Eigen::VectorXd> seed_x; // each seed's best point, in seed order
    std::vector<double> seed_f;
    Eigen::VectorXd spread;       // standard deviation over the seeds of each parameter
    int seeds_at_best = 0;        // seeds whose f is within 1e-6 relative of the best
    pmsm::LinearModel linearised; // the residuals linearised at best_x
};

// Throws std::invalid_argument for an unknown algorithm, std::runtime_error if every seed fails.
OutputIdentification identify_output_error(const pmsm::OutputErrorProblem& problem,
                                           const OutputIdentificationOptions& options);

} // namespace mhb
