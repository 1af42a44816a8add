#include "problems/problem.hpp"

#include <cmath>
#include <stdexcept>

namespace mhb {

bool Box::contains(const Eigen::VectorXd& x) const {
    return x.size() == lower.size() && (x.array() >= lower.array()).all() &&
           (x.array() <= upper.array()).all();
}

void Box::validate(const std::string& owner) const {
    if (lower.size() == 0 || lower.size() != upper.size())
        throw std::invalid_argument(owner + ": bounds must be non-empty and of equal size");
    for (Eigen::Index i = 0; i < lower.size(); ++i) {
        if (!std::isfinite(lower[i]) || !std::isfinite(upper[i]) || !(lower[i] < upper[i]))
            throw std::invalid_argument(owner + ": bounds of coordinate " + std::to_string(i) +
                                        " must be finite with lower < upper");
    }
}

} // namespace mhb
