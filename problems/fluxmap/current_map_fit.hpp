// The least-squares fit of a current map to a flux map: a bounded Levenberg-Marquardt method from
// many starts drawn uniformly from the box with the project's Rng. It finds the best-known
// optimum that the `fluxmap` family ships for its data (data/README.md) and is the fit that
// `mhbench identify` may reuse.
//
// One start: the parameters are scaled to [0, 1] by the box (the exponents and the coefficients
// differ by orders of magnitude), the Jacobian is taken by central differences in those scaled
// coordinates, and each step solves (J'J + mu diag(J'J)) dz = -J'r on the free coordinates (a
// coordinate at a bound whose gradient points out of the box is held there), then is projected
// onto the box. mu falls after a success and rises after a failure; a start ends when f has not
// fallen by more than 1e-15 relative in 10 consecutive accepted steps, or after max_iterations.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "problems/fluxmap/current_map.hpp"
#include "problems/problem.hpp"

namespace mhb::fluxmap {

struct FitOptions {
    int starts = 100;
    std::uint64_t seed = 1;
    int max_iterations = 2000;
};

struct FitResult {
    Eigen::VectorXd theta; // the best of all starts
    double f = 0.0;
    std::vector<double> start_f; // the end value of each start, in start order
    // How many starts ended within `relative` of the best f.
    [[nodiscard]] int reached(double relative) const;
};

// Central differences in coordinates scaled by the box: column j is dr/dz_j with
// z_j = (theta_j - lower_j) / (upper_j - lower_j); a step never leaves the box. Divide column j by the
// box's width j for dr/dtheta_j.
Eigen::MatrixXd scaled_jacobian(const CurrentMap& map, const Box& box, const Eigen::VectorXd& theta);
// The starts of fit_multistart, in its order: `lower + u (upper - lower)`, u drawn by Rng(seed).
std::vector<Eigen::VectorXd> multistart_points(const Box& box, int starts, std::uint64_t seed);
// One bounded LM descent from `start` (inside `box`).
FitResult fit_from(const CurrentMap& map, const Box& box, const Eigen::VectorXd& start, int max_iterations);
// The multi-start fit: starts drawn by Rng(options.seed), `box.lower + u (box.upper - box.lower)`.
FitResult fit_multistart(const CurrentMap& map, const Box& box, const FitOptions& options);

} // namespace mhb::fluxmap
