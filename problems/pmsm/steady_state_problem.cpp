#include "problems/pmsm/steady_state_problem.hpp"

#include <stdexcept>

namespace mhb::pmsm {

Box paper_bounds() {
    return Box{Eigen::Vector4d(0.0, 0.0, 0.0, 0.0), Eigen::Vector4d(0.5, 0.01, 0.01, 0.1)};
}

SteadyStateProblem::SteadyStateProblem(const Dataset& data, const FitnessWeights& weights, Box bounds,
                                       FitnessEvaluation evaluation)
    : samples_(pair_samples(data, weights)), box_(std::move(bounds)),
      direct_(evaluation == FitnessEvaluation::direct), truth_(data.true_parameters()) {
    box_.validate("pmsm");
    if (box_.dimension() != 4)
        throw std::invalid_argument("pmsm: bounds must have 4 coordinates (Rs, Ld, Lq, psi)");
    least_squares_ = solve_least_squares(samples_, &box_);
    expanded_ = ExpandedFitness(samples_, least_squares_.theta);
}

double SteadyStateProblem::evaluate(const Eigen::VectorXd& x) const {
    if (x.size() != 4)
        throw std::logic_error("pmsm: evaluate needs 4 coordinates (Rs, Ld, Lq, psi)");
    return direct_ ? samples_.fitness(x) : expanded_(x);
}

std::optional<KnownOptimum> SteadyStateProblem::known_optimum() const {
    // f* through evaluate() itself, so f - f* is measured on one scale (at the unconstrained
    // optimum the expansion gives the direct sum exactly).
    const Eigen::VectorXd x = least_squares_.box_theta;
    return KnownOptimum{evaluate(x), x};
}

std::optional<Eigen::VectorXd> SteadyStateProblem::true_parameters() const {
    if (!truth_)
        return std::nullopt;
    return Eigen::VectorXd(*truth_);
}

} // namespace mhb::pmsm
