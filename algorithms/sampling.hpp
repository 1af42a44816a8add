// Small helpers shared by population-based optimisers.
#pragma once

#include <Eigen/Core>

#include "problems/core/rng.hpp"
#include "problems/problem.hpp"

namespace mhb {

// A point drawn uniformly in the box, coordinate by coordinate in index order (eq. 5 of the
// ITLBO paper: x = lo + rand * (hi - lo)).
inline Eigen::VectorXd uniform_point(const Box& box, Rng& rng) {
    Eigen::VectorXd x(box.dimension());
    for (Eigen::Index k = 0; k < x.size(); ++k)
        x[k] = box.lower[k] + rng.uniform() * (box.upper[k] - box.lower[k]);
    return x;
}

} // namespace mhb
