#include "problems/pmsm/linear_model.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mhb::pmsm {
namespace {

constexpr double rank_tolerance = 1e-10;        // relative to the largest singular value
constexpr double null_tolerance = 1e-6;         // a parameter's component in the null space
constexpr Eigen::Index max_box_parameters = 10; // 3^10 = 59049 active sets

void validate(const LinearModel& model, const Box* box) {
    const Eigen::Index m = model.equations(), k = model.parameters();
    if (m == 0 || k == 0)
        throw std::invalid_argument("pmsm: the linear model is empty (" + std::to_string(m) + " equations, " +
                                    std::to_string(k) + " parameters)");
    if (model.b.size() != m)
        throw std::invalid_argument("pmsm: the linear model has " + std::to_string(m) + " rows in A but " +
                                    std::to_string(model.b.size()) + " in b");
    if (!model.parameter_names.empty() && static_cast<Eigen::Index>(model.parameter_names.size()) != k)
        throw std::invalid_argument("pmsm: the linear model names " +
                                    std::to_string(model.parameter_names.size()) + " parameters for " +
                                    std::to_string(k) + " columns");
    if (model.d_rows < 0 || model.d_rows > m)
        throw std::invalid_argument("pmsm: the linear model's d_rows is outside [0, equations]");
    for (std::size_t i = 0; i < model.run_starts.size(); ++i)
        if (model.run_starts[i] < 0 || (i > 0 && model.run_starts[i] <= model.run_starts[i - 1]))
            throw std::invalid_argument(
                "pmsm: the linear model's run_starts must be increasing offsets >= 0");
    if (!model.A.allFinite() || !model.b.allFinite())
        throw std::invalid_argument("pmsm: the linear model has a non-finite entry in A or b");
    if (box != nullptr && box->dimension() != k)
        throw std::invalid_argument("pmsm: the search box has " + std::to_string(box->dimension()) +
                                    " coordinates for " + std::to_string(k) + " parameters");
    if (box != nullptr && k > max_box_parameters)
        throw std::invalid_argument("pmsm: the exact box-constrained optimum tries all 3^k active sets, "
                                    "too many for k = " +
                                    std::to_string(k));
}

// RMS, maximum and lag-1 autocorrelation of r[begin, end). The autocorrelation is the standard
// estimate sum (r_i - mean)(r_i+1 - mean) / sum (r_i - mean)^2, but the products pair only
// neighbours of one run: the last equation of a run and the first of the next are not one
// period apart (a time jump, another dataset), so their product says nothing about whiteness.
ResidualStats residual_stats(const Eigen::VectorXd& r, Eigen::Index begin, Eigen::Index end,
                             const std::vector<Eigen::Index>& run_starts) {
    ResidualStats s;
    const Eigen::Index n = end - begin;
    s.lag1 = std::numeric_limits<double>::quiet_NaN();
    if (n == 0)
        return s;
    const auto axis = r.segment(begin, n);
    s.rms = std::sqrt(axis.squaredNorm() / static_cast<double>(n));
    s.max_abs = axis.cwiseAbs().maxCoeff();
    if (n < 3)
        return s;
    const double mean = axis.mean();
    double c0 = 0.0, c1 = 0.0;
    std::size_t next_run = 1; // index into run_starts of the next run to begin
    for (Eigen::Index i = 0; i < n; ++i) {
        const double x = axis[i] - mean;
        c0 += x * x;
        if (i + 1 == n)
            break;
        while (next_run < run_starts.size() && run_starts[next_run] <= i)
            ++next_run;
        const bool same_run = next_run >= run_starts.size() || run_starts[next_run] != i + 1;
        if (same_run)
            c1 += x * (axis[i + 1] - mean);
    }
    if (c0 > 0.0)
        s.lag1 = c1 / c0;
    return s;
}

// The least-squares problem in scaled units y = scale .* theta, reduced to its p = min(m, k)
// rows through the thin SVD: |b - As y|^2 = |c - R y|^2 + |b_perp|^2 with R = S V^T, c = U^T b.
// The active-set search solves 3^k sub-problems on it, k rows each instead of m.
struct Reduced {
    Eigen::MatrixXd R;
    Eigen::VectorXd c;
};

// min |c - R y|^2 over y with the coordinates where `choice` is -1/+1 fixed at lower/upper (scaled
// units) and the others free. False when the free columns are rank-deficient: a box optimum whose
// free columns are dependent can slide along their null space to another bound without changing f,
// so some other active set, with independent free columns, attains the same optimum.
bool solve_active_set(const Reduced& red, const std::vector<int>& choice, const Eigen::VectorXd& lower,
                      const Eigen::VectorXd& upper, Eigen::VectorXd& y) {
    const Eigen::Index k = red.R.cols();
    std::vector<Eigen::Index> free;
    Eigen::VectorXd rhs = red.c;
    for (Eigen::Index j = 0; j < k; ++j) {
        const int a = choice[static_cast<std::size_t>(j)];
        if (a == 0) {
            free.push_back(j);
            continue;
        }
        y[j] = a < 0 ? lower[j] : upper[j];
        rhs -= red.R.col(j) * y[j];
    }
    const auto nf = static_cast<Eigen::Index>(free.size());
    if (nf == 0)
        return true;
    if (nf > red.R.rows())
        return false;
    Eigen::MatrixXd Rf(red.R.rows(), nf);
    for (Eigen::Index c = 0; c < nf; ++c)
        Rf.col(c) = red.R.col(free[static_cast<std::size_t>(c)]);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Rf);
    qr.setThreshold(rank_tolerance);
    if (qr.rank() < nf)
        return false;
    const Eigen::VectorXd yf = qr.solve(rhs);
    for (Eigen::Index c = 0; c < nf; ++c)
        y[free[static_cast<std::size_t>(c)]] = yf[c];
    return true;
}

} // namespace

double LinearModel::fitness(const Eigen::Ref<const Eigen::VectorXd>& theta) const {
    if (theta.size() != A.cols())
        throw std::logic_error("pmsm: linear model fitness needs " + std::to_string(A.cols()) +
                               " parameters");
    double f = 0.0;
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
        const double r = b[i] - A.row(i).dot(theta);
        f += r * r;
    }
    return f;
}

LinearFit fit_linear_model(const LinearModel& model, const Box* box) {
    validate(model, box);
    const Eigen::Index m = model.equations(), k = model.parameters();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();

    // Unit-norm columns make the rank test and the condition number independent of units (ohm
    // and henry differ by 1e3 here); a zero column stays zero and shows as a null direction.
    Eigen::VectorXd scale = model.A.colwise().norm().transpose();
    for (Eigen::Index j = 0; j < k; ++j)
        if (scale[j] == 0.0)
            scale[j] = 1.0;
    const Eigen::MatrixXd As = model.A * scale.cwiseInverse().asDiagonal();

    // Full V: with m < k the null space has more directions than there are singular values.
    const Eigen::JacobiSVD<Eigen::MatrixXd, Eigen::ColPivHouseholderQRPreconditioner> svd(
        As, Eigen::ComputeThinU | Eigen::ComputeFullV);
    const Eigen::VectorXd& sv = svd.singularValues();
    const Eigen::MatrixXd& U = svd.matrixU();
    const Eigen::MatrixXd& V = svd.matrixV();
    const Eigen::Index p = sv.size();

    LinearFit fit;
    fit.rank = 0;
    while (fit.rank < p && sv[fit.rank] > rank_tolerance * sv[0])
        ++fit.rank;
    const Eigen::Index r = fit.rank;
    fit.condition_number = r < k ? inf : sv[0] / sv[k - 1];

    // Minimum-norm solution in scaled units, y = V_r S_r^-1 U_r^T b, with one step of iterative
    // refinement (the correction solves the same problem for the residual).
    const auto solve = [&](const Eigen::VectorXd& rhs) -> Eigen::VectorXd {
        const Eigen::VectorXd coeffs = U.leftCols(r).transpose() * rhs;
        return V.leftCols(r) * coeffs.cwiseQuotient(sv.head(r));
    };
    Eigen::VectorXd y = solve(model.b);
    y += solve(model.b - As * y);
    fit.theta = y.cwiseQuotient(scale);
    fit.f = model.fitness(fit.theta);
    if (!fit.theta.allFinite() || !std::isfinite(fit.f))
        throw std::invalid_argument("pmsm: the least-squares estimate is not finite: the data's values are "
                                    "too large for double precision");

    // A parameter is determined when the null space (the right singular vectors of the dropped
    // singular values) has no component along it: then e_j lies in A's row space and theta_j is
    // the same for every least-squares solution.
    fit.weakest_direction = V.col(k - 1).cwiseAbs();
    fit.determined.assign(static_cast<std::size_t>(k), true);
    for (Eigen::Index j = 0; j < k; ++j)
        fit.determined[static_cast<std::size_t>(j)] = V.row(j).tail(k - r).norm() <= null_tolerance;

    // sigma2 (A^T A)^+ from the SVD, never forming A^T A (which would square the condition number);
    // exact for the determined parameters, whose variances the pseudo-inverse gives correctly.
    fit.sigma2 = m > k ? fit.f / static_cast<double>(m - k) : nan;
    const Eigen::MatrixXd w = V.leftCols(r) * sv.head(r).cwiseInverse().asDiagonal();
    const Eigen::MatrixXd scaled_inverse = w * w.transpose();
    fit.covariance =
        fit.sigma2 * (scale.cwiseInverse().asDiagonal() * scaled_inverse * scale.cwiseInverse().asDiagonal());
    for (Eigen::Index j = 0; j < k; ++j)
        if (!fit.determined[static_cast<std::size_t>(j)]) {
            fit.covariance.row(j).setConstant(inf);
            fit.covariance.col(j).setConstant(inf);
        }
    fit.standard_error = fit.covariance.diagonal().cwiseSqrt();

    const Eigen::VectorXd residual = model.b - model.A * fit.theta;
    fit.residual_d = residual_stats(residual, 0, model.d_rows, model.run_starts);
    fit.residual_q = residual_stats(residual, model.d_rows, m, model.run_starts);

    fit.box_theta = fit.theta;
    fit.box_f = fit.f;
    fit.active_bound.assign(static_cast<std::size_t>(k), 0);
    if (box == nullptr || box->contains(fit.theta))
        return fit;

    // Outside the box: the optimum of a convex QP is the unconstrained optimum of its own active
    // set, so trying every lower/free/upper choice and keeping the best feasible one is exact.
    fit.inside_box = false;
    const Reduced red{sv.asDiagonal() * V.leftCols(p).transpose(), U.transpose() * model.b};
    const Eigen::VectorXd lower = box->lower.cwiseProduct(scale), upper = box->upper.cwiseProduct(scale);
    double best = inf;
    std::vector<int> choice(static_cast<std::size_t>(k), -1); // -1, 0, +1 per coordinate
    Eigen::VectorXd candidate(k);
    for (;;) {
        if (solve_active_set(red, choice, lower, upper, candidate)) {
            Eigen::VectorXd theta = candidate.cwiseQuotient(scale);
            for (Eigen::Index j = 0; j < k; ++j) // exactly on the bound, not rounded through the scale
                if (const int a = choice[static_cast<std::size_t>(j)]; a != 0)
                    theta[j] = a < 0 ? box->lower[j] : box->upper[j];
            // Compared on the reduced system, which differs from f by a constant.
            const double value = (red.c - red.R * candidate).squaredNorm();
            if (box->contains(theta) && value < best) {
                best = value;
                fit.box_theta = theta;
                fit.active_bound = choice;
            }
        }
        std::size_t j = 0; // next choice, counting in base 3
        while (j < choice.size() && choice[j] == 1)
            choice[j++] = -1;
        if (j == choice.size())
            break;
        ++choice[j];
    }
    fit.box_f = model.fitness(fit.box_theta);
    return fit;
}

} // namespace mhb::pmsm
