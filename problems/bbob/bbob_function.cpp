#include "problems/bbob/bbob_function.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "problems/bbob/bbob_random.hpp"
#include "problems/bbob/bbob_transforms.hpp"

namespace mhb::bbob {

std::unique_ptr<Function> make_function(int function, Eigen::Index dimension, std::int64_t instance) {
    if (function < 1 || function > 24)
        throw std::invalid_argument("bbob: function f" + std::to_string(function) +
                                    " does not exist; f is 1-24");
    if (dimension < 2 || dimension > max_dimension)
        throw std::invalid_argument("bbob: dimension " + std::to_string(dimension) + " is outside [2, " +
                                    std::to_string(max_dimension) + "]");
    if (instance < 1)
        throw std::invalid_argument("bbob: instance " + std::to_string(instance) + " must be >= 1");
    InstanceSetup setup;
    setup.function = function;
    setup.dimension = dimension;
    setup.instance = instance;
    setup.rseed = instance_seed(function, instance);
    setup.f_opt = legacy_fopt(function, instance);
    if (function <= 5)
        return make_separable(setup);
    if (function <= 9)
        return make_moderate(setup);
    if (function <= 14)
        return make_ill_conditioned(setup);
    if (function <= 19)
        return make_multimodal(setup);
    return make_weakly_structured(setup);
}

ScaledRotationFrame scaled_rotation_frame(std::int64_t rseed, Eigen::Index dimension) {
    const double factor = std::max(1.0, std::sqrt(static_cast<double>(dimension)) / 8.0);
    const Eigen::MatrixXd r = legacy_rotation(rseed, dimension);
    return {factor * r, r.transpose() * Eigen::VectorXd::Ones(dimension) / (2.0 * factor)};
}

Eigen::MatrixXd rotate_scale_rotate(const Eigen::MatrixXd& r, const Eigen::VectorXd& scales,
                                    const Eigen::MatrixXd& q) {
    // Summed in the legacy order (k innermost, left to right) so that the product matches COCO's.
    const Eigen::Index n = r.rows();
    Eigen::MatrixXd m(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) {
            double sum = 0.0;
            for (Eigen::Index k = 0; k < n; ++k)
                sum += r(i, k) * scales[k] * q(k, j);
            m(i, j) = sum;
        }
    return m;
}

} // namespace mhb::bbob
