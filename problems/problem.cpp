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

void Problem::evaluate_many(std::span<const Eigen::VectorXd> x, std::span<double> f) const {
    if (f.size() != x.size())
        throw std::logic_error("Problem::evaluate_many: " + std::to_string(x.size()) + " points, " +
                               std::to_string(f.size()) + " places for values");
    for (std::size_t i = 0; i < x.size(); ++i)
        f[i] = evaluate(x[i]);
}

} // namespace mhb
