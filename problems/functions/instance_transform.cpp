#include "problems/functions/instance_transform.hpp"

#include <Eigen/QR>
#include <bit>
#include <string>

#include "problems/core/rng.hpp"

namespace mhb {

std::uint64_t instance_seed(std::string_view family, std::string_view purpose,
                            std::int64_t instance) noexcept {
    return mix64(mix64(stable_hash(family) ^ stable_hash(purpose)) ^ static_cast<std::uint64_t>(instance));
}

Eigen::VectorXd draw_shift(std::string_view family, std::int64_t instance, const Box& box) {
    Rng rng(instance_seed(family, "shift", instance));
    Eigen::VectorXd c(box.dimension());
    for (Eigen::Index i = 0; i < c.size(); ++i) {
        const double centre = 0.5 * (box.lower[i] + box.upper[i]);
        const double half_width = 0.5 * (box.upper[i] - box.lower[i]);
        c[i] = centre + 0.8 * half_width * (2.0 * rng.uniform() - 1.0);
    }
    return c;
}

Eigen::MatrixXd draw_rotation(std::string_view family, std::int64_t instance, Eigen::Index dimension) {
    Rng rng(instance_seed(family, "rotation/" + std::to_string(dimension), instance));
    Eigen::MatrixXd gaussian(dimension, dimension);
    for (Eigen::Index j = 0; j < dimension; ++j)
        for (Eigen::Index i = 0; i < dimension; ++i)
            gaussian(i, j) = rng.normal();
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(gaussian);
    Eigen::MatrixXd q = qr.householderQ();
    // det Q is (-1) per non-trivial Householder reflection; each sign flip below changes it again.
    bool negative = false;
    for (Eigen::Index k = 0; k < qr.hCoeffs().size(); ++k)
        negative ^= qr.hCoeffs()[k] != 0.0;
    for (Eigen::Index j = 0; j < dimension; ++j)
        if (qr.matrixQR()(j, j) < 0.0) {
            q.col(j) = -q.col(j);
            negative = !negative;
        }
    if (negative)
        q.col(0) = -q.col(0);
    return q;
}

double hash_uniform(std::uint64_t seed, const Eigen::VectorXd& x) noexcept {
    std::uint64_t h = mix64(seed);
    for (Eigen::Index i = 0; i < x.size(); ++i)
        h = mix64(h ^ std::bit_cast<std::uint64_t>(x[i]));
    return static_cast<double>(h >> 11) * 0x1.0p-53;
}

} // namespace mhb
