#include "problems/pmsm/least_squares.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mhb::pmsm {
namespace {

// Least squares on the columns `free` of A (the others fixed at `fixed_values`), with columns
// scaled to unit norm and one step of iterative refinement. Returns false if rank-deficient.
bool solve_subset(const WeightedSystem& sys, const std::array<bool, 4>& free,
                  const Eigen::Vector4d& fixed_values, Eigen::Vector4d& theta) {
    std::array<Eigen::Index, 4> cols{};
    Eigen::Index k = 0;
    Eigen::VectorXd rhs = sys.b;
    theta = fixed_values;
    for (Eigen::Index j = 0; j < 4; ++j) {
        if (free[static_cast<std::size_t>(j)])
            cols[static_cast<std::size_t>(k++)] = j;
        else
            rhs -= sys.A.col(j) * fixed_values[j];
    }
    if (k == 0)
        return true;
    Eigen::MatrixXd As(sys.A.rows(), k);
    Eigen::VectorXd scale(k);
    for (Eigen::Index c = 0; c < k; ++c) {
        const auto j = cols[static_cast<std::size_t>(c)];
        scale[c] = sys.A.col(j).norm();
        if (scale[c] == 0.0)
            return false;
        As.col(c) = sys.A.col(j) / scale[c];
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(As);
    if (qr.rank() < k)
        return false;
    Eigen::VectorXd y = qr.solve(rhs);
    const Eigen::VectorXd residual = rhs - As * y; // refinement: solve for the correction once
    y += qr.solve(residual);
    for (Eigen::Index c = 0; c < k; ++c)
        theta[cols[static_cast<std::size_t>(c)]] = y[c] / scale[c];
    return true;
}

} // namespace

LeastSquaresResult solve_least_squares(const SteadyStateData& data, const Box* box) {
    const WeightedSystem sys = weighted_system(data);
    LeastSquaresResult r;
    if (!solve_subset(sys, {true, true, true, true}, Eigen::Vector4d::Zero(), r.theta))
        throw std::invalid_argument(
            "pmsm: the data (with these weights) do not determine all four parameters; "
            "both injection states need samples with non-zero weights");
    r.f = data.fitness(r.theta);
    if (!r.theta.allFinite() || !std::isfinite(r.f))
        throw std::invalid_argument("pmsm: the least-squares estimate is not finite: the data's values are "
                                    "too large for double precision");

    // Covariance sigma^2 (A^T W A)^-1, through the column-scaled design for accuracy.
    Eigen::Vector4d scale;
    Eigen::MatrixXd As(sys.A.rows(), 4);
    for (Eigen::Index j = 0; j < 4; ++j) {
        scale[j] = sys.A.col(j).norm();
        As.col(j) = sys.A.col(j) / scale[j];
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(As, Eigen::ComputeThinV);
    const Eigen::Vector4d sv = svd.singularValues();
    r.condition_number = sv[0] / sv[3];
    if (!(sv[3] > 0) || !std::isfinite(r.condition_number))
        throw std::invalid_argument("pmsm: the normal equations are singular (the data, with these weights, "
                                    "do not determine all four parameters)");
    const Eigen::Matrix4d v = svd.matrixV();
    const Eigen::Matrix4d scaled_inverse = v * sv.cwiseInverse().cwiseAbs2().asDiagonal() * v.transpose();
    const Eigen::Matrix4d inverse =
        scale.cwiseInverse().asDiagonal() * scaled_inverse * scale.cwiseInverse().asDiagonal();

    int m = 0;
    for (Eigen::Index i = 0; i < data.ud.size(); ++i)
        m += (data.weight_d[i] > 0 ? 1 : 0) + (data.weight_q[i] > 0 ? 1 : 0);
    r.equations = m;
    r.sigma2 = m > 4 ? r.f / (m - 4) : std::numeric_limits<double>::quiet_NaN();
    r.covariance = r.sigma2 * inverse;
    r.standard_error = r.covariance.diagonal().cwiseSqrt();

    const Eigen::ArrayXd rd = data.ud - r.theta[0] * data.id + r.theta[2] * data.omega_iq;
    const Eigen::ArrayXd rq =
        data.uq - r.theta[0] * data.iq - r.theta[1] * data.omega_id - r.theta[3] * data.omega;
    r.residual_rms_d = std::sqrt(rd.square().mean());
    r.residual_rms_q = std::sqrt(rq.square().mean());

    r.box_theta = r.theta;
    r.box_f = r.f;
    if (box == nullptr || box->contains(r.theta))
        return r;

    // Outside the box: the best feasible optimum over all 81 active sets.
    r.inside_box = false;
    r.box_f = std::numeric_limits<double>::infinity();
    for (int code = 0; code < 81; ++code) {
        std::array<bool, 4> free{};
        Eigen::Vector4d fixed = Eigen::Vector4d::Zero();
        int c = code;
        for (Eigen::Index j = 0; j < 4; ++j, c /= 3) {
            const int choice = c % 3; // 0 free, 1 lower, 2 upper
            free[static_cast<std::size_t>(j)] = choice == 0;
            fixed[j] = choice == 1 ? box->lower[j] : (choice == 2 ? box->upper[j] : 0.0);
        }
        Eigen::Vector4d theta;
        if (!solve_subset(sys, free, fixed, theta) || !box->contains(theta))
            continue;
        const double f = data.fitness(theta);
        if (f < r.box_f) {
            r.box_f = f;
            r.box_theta = theta;
        }
    }
    return r;
}

} // namespace mhb::pmsm
