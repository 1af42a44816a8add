#include "problems/pmsm/expanded_fitness.hpp"

#include <Eigen/QR>

namespace mhb::pmsm {

ExpandedFitness::ExpandedFitness(const SteadyStateData& s, const Eigen::Vector4d& theta0)
    : theta0_(theta0), f0_(s.fitness(theta0)) {
    const WeightedSystem sys = weighted_system(s);
    // g0 = -A^T W r0, from the residuals at theta0.
    g0_ = -(sys.A.transpose() * (sys.b - sys.A * theta0));
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(sys.A);
    r_ = qr.matrixQR().topRows(4).triangularView<Eigen::Upper>();
}

} // namespace mhb::pmsm
