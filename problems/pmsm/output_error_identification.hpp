// The output-error identification of `mhbench identify --model output`, the part that is the
// PMSM's: the model has no closed-form optimum, so an optimiser is run from several seeds and
// their best points are summarised here: the best point found is the estimate, the spread of the
// seeds' answers is one error estimate, and the residuals linearised at the estimate (a
// finite-difference Jacobian) give the other, with the same verdicts as the linear models.
//
// Running the optimiser is not here: problems/ knows no optimiser (algorithms/ builds on
// problems/, not the reverse), so the search over seeds, which builds one from the algorithm
// registry and runs it through execute_run, is runner/single_problem/output_error_search.hpp.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "problems/pmsm/linear_model.hpp"
#include "problems/pmsm/output_error_problem.hpp"

namespace mhb::pmsm {

struct OutputIdentification {
    Eigen::VectorXd best_x; // the best point of all seeds
    double best_f = 0.0;
    std::vector<Eigen::VectorXd> seed_x; // each seed's best point, in seed order
    std::vector<double> seed_f;
    Eigen::VectorXd spread; // standard deviation over the seeds of each parameter
    int seeds_at_best = 0;  // seeds whose f is within 1e-6 relative of the best
    LinearModel linearised; // the residuals linearised at best_x
};

// The residuals r(theta) linearised at theta0 as the linear model b - A theta = r(theta0) + J
// (theta - theta0), J by central differences with steps of 1e-6 of each coordinate's box width.
LinearModel linearise_residuals(const OutputErrorProblem& problem, const Eigen::VectorXd& theta0);

// The identification from each seed's best point and value (in seed order, at least one, each of
// the problem's dimension): the best of them, the spread and the linearisation at the best.
// Throws std::invalid_argument when `seed_x` is empty or its sizes disagree.
OutputIdentification summarise_seeds(const OutputErrorProblem& problem, std::vector<Eigen::VectorXd> seed_x,
                                     std::vector<double> seed_f);

} // namespace mhb::pmsm
