// Numbers and numeric comparisons shared by the tests: infinity, and the largest absolute and
// relative differences between two series.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace mhb::test_support {

inline constexpr double inf = std::numeric_limits<double>::infinity();

// max_k |a[k] - b[k]| over the first a.size() entries (b at least as long).
inline double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
        m = std::max(m, std::fabs(a[k] - b[k]));
    return m;
}

// max_i |x_i - truth_i| / truth_i (truth without zeros).
inline double max_relative_error(const Eigen::VectorXd& x, const Eigen::VectorXd& truth) {
    return ((x - truth).array() / truth.array()).abs().maxCoeff();
}

} // namespace mhb::test_support
