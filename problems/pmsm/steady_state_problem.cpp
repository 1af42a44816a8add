#include "problems/pmsm/steady_state_problem.hpp"

#include <cmath>
#include <stdexcept>

#include "problems/core/parameters.hpp"

namespace mhb::pmsm {

Box paper_bounds() {
    return Box{Eigen::Vector4d(0.0, 0.0, 0.0, 0.0), Eigen::Vector4d(0.5, 0.01, 0.01, 0.1)};
}

SteadyStateProblem::SteadyStateProblem(const Dataset& data, const FitnessWeights& weights, Box bounds,
                                       FitnessEvaluation evaluation)
    : SteadyStateProblem(pair_samples(data, weights), data.true_parameters(), std::move(bounds), evaluation) {
}

SteadyStateProblem::SteadyStateProblem(SteadyStateData samples, std::optional<Eigen::Vector4d> truth,
                                       Box bounds, FitnessEvaluation evaluation)
    : samples_(std::move(samples)), box_(std::move(bounds)), direct_(evaluation == FitnessEvaluation::direct),
      truth_(std::move(truth)) {
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

std::vector<std::string> SteadyStateProblem::warnings() const {
    std::vector<std::string> out;
    if (least_squares_.inside_box)
        return out;
    const char* names[] = {"Rs", "Ld", "Lq", "psi"};
    const char* keys[] = {"rs", "ld", "lq", "psi"};
    for (int j = 0; j < 4; ++j) {
        const double x = least_squares_.box_theta[j];
        const bool low = x == box_.lower[j];
        if (!low && x != box_.upper[j])
            continue;
        out.push_back(std::string("the least-squares optimum lies outside the search box: f* is the "
                                  "box-constrained optimum, with ") +
                      names[j] + " on its " + (low ? "lower" : "upper") + " bound " + format_real(x) +
                      " (unconstrained: " + names[j] + " = " + format_real(least_squares_.theta[j]) +
                      "); widen it (" + keys[j] + "=lo:hi) if the motor may lie there");
    }
    return out;
}

} // namespace mhb::pmsm
