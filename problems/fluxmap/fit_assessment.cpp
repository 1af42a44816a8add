// The assessment of fit_assessment.hpp: covariance from the Jacobian at the estimate, verdicts by
// the PMSM identify's thresholds, current errors and the spread of the starts.
#include "problems/fluxmap/fit_assessment.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "problems/fluxmap/current_map_fit.hpp"

namespace mhb::fluxmap {
namespace {

constexpr double weak_relative_error = 0.05;  // r above this: weakly determined
constexpr double absent_relative_error = 0.5; // r above this: not determined
constexpr double weak_condition = 1e5;        // kappa above this and a share of the weakest
constexpr double absent_condition = 1e8;      // direction above weak_share: weakly / not
constexpr double weak_share = 0.1;            // determined
constexpr double reported_correlation = 0.9;  // |correlation| above this is named in the reason

std::string number(const char* format, double value) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, value);
    return buf;
}

// A parameter within 1e-9 of the box's width of a bound is held there by the box.
double bound_tolerance(const Box& box, Eigen::Index j) {
    return 1e-9 * (box.upper[j] - box.lower[j]);
}

bool on_lower_bound(const Box& box, Eigen::Index j, double value) {
    return value <= box.lower[j] + bound_tolerance(box, j);
}

bool on_bound(const Box& box, Eigen::Index j, double value) {
    return on_lower_bound(box, j, value) || value >= box.upper[j] - bound_tolerance(box, j);
}

// Lag-1 autocorrelation of the residuals of both axes, each axis's mean removed, pooled.
double neighbour_correlation(const Eigen::VectorXd& r, Eigen::Index n) {
    double numerator = 0.0, denominator = 0.0;
    for (const Eigen::Index start : {Eigen::Index{0}, n}) {
        const Eigen::VectorXd x = r.segment(start, n).array() - r.segment(start, n).mean();
        numerator += x.head(n - 1).dot(x.tail(n - 1));
        denominator += x.squaredNorm();
    }
    return denominator > 0 ? numerator / denominator : 0.0;
}

// The free parameters' covariance and the weakest direction of their unit-norm design.
struct FreeFit {
    std::vector<Eigen::Index> free;
    Eigen::MatrixXd covariance; // over `free`, theta units
    Eigen::VectorXd weakest;    // |v_min| by free parameter
    double condition = 0.0;
};

FreeFit free_fit(const CurrentMap& map, const Box& box, const Eigen::VectorXd& theta, double sigma2) {
    const Eigen::MatrixXd scaled = scaled_jacobian(map, box, theta);
    FreeFit out;
    for (Eigen::Index j = 0; j < theta.size(); ++j)
        if (!on_bound(box, j, theta[j]))
            out.free.push_back(j);
    const auto p = static_cast<Eigen::Index>(out.free.size());
    Eigen::MatrixXd design(scaled.rows(), p);
    Eigen::VectorXd norms(p);
    for (Eigen::Index c = 0; c < p; ++c) {
        const Eigen::Index j = out.free[static_cast<std::size_t>(c)];
        const Eigen::VectorXd column = scaled.col(j) / (box.upper[j] - box.lower[j]); // dr/dtheta_j
        norms[c] = column.norm();
        design.col(c) = norms[c] > 0 ? Eigen::VectorXd(column / norms[c]) : column;
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(design, Eigen::ComputeThinV);
    const Eigen::VectorXd& s = svd.singularValues();
    const double smallest = p > 0 ? s[p - 1] : 0.0;
    out.condition = p > 0 && smallest > 0 ? s[0] / smallest : std::numeric_limits<double>::infinity();
    out.weakest = p > 0 ? Eigen::VectorXd(svd.matrixV().col(p - 1).cwiseAbs()) : Eigen::VectorXd();
    const double infinity = std::numeric_limits<double>::infinity();
    const Eigen::VectorXd inverse_s2 =
        s.unaryExpr([&](double v) { return v > s[0] * 1e-15 ? 1.0 / (v * v) : infinity; });
    const Eigen::MatrixXd& v = svd.matrixV();
    Eigen::MatrixXd unit_covariance = Eigen::MatrixXd::Zero(p, p);
    for (Eigen::Index k = 0; k < p; ++k)
        if (std::isfinite(inverse_s2[k]))
            unit_covariance += inverse_s2[k] * v.col(k) * v.col(k).transpose();
    out.covariance =
        sigma2 * norms.cwiseInverse().asDiagonal() * unit_covariance * norms.cwiseInverse().asDiagonal();
    if (!std::isfinite(out.condition) || out.condition > 1e15)
        out.covariance.diagonal().setConstant(infinity);
    return out;
}

void judge(ParameterAssessment& a, double weakest_share, double condition) {
    const bool collinear = weakest_share > weak_share;
    const std::string error_text =
        std::isfinite(a.relative_error)
            ? "standard error " + number("%.3g", 100 * a.relative_error) + " % of the estimate"
            : "no standard error (the map does not determine it)";
    const std::string trade = a.partner.empty()
                                  ? std::string()
                                  : "; correlation with " + a.partner + " " + number("%.4f", a.correlation);
    if (!(a.relative_error <= absent_relative_error) || (collinear && condition > absent_condition))
        a.verdict = Determination::not_determined;
    else if (a.relative_error > weak_relative_error || (collinear && condition > weak_condition))
        a.verdict = Determination::weakly;
    else
        a.verdict = Determination::well;
    a.reason = error_text + trade;
    if (collinear && condition > weak_condition)
        a.reason += "; " + number("%.2g", weakest_share) + " of the weakest direction at condition number " +
                    number("%.3g", condition);
}

} // namespace

const char* to_string(Determination determination) {
    switch (determination) {
    case Determination::well:
        return "well determined";
    case Determination::weakly:
        return "weakly determined";
    case Determination::not_determined:
        return "not determined";
    }
    return "?";
}

CurrentErrors current_errors(const CurrentMap& map, const Eigen::VectorXd& theta) {
    Eigen::VectorXd r;
    map.residuals(theta, r);
    const Eigen::Index n = map.points();
    const Eigen::ArrayXd e_d = r.head(n).array(), e_q = r.tail(n).array();
    const Eigen::ArrayXd magnitude2 = e_d.square() + e_q.square();
    CurrentErrors out;
    out.rms_d = std::sqrt(e_d.square().mean());
    out.rms_q = std::sqrt(e_q.square().mean());
    out.rms = std::sqrt(magnitude2.mean());
    out.worst = std::sqrt(magnitude2.maxCoeff(&out.worst_point));
    out.neighbour_correlation = n > 1 ? neighbour_correlation(r, n) : 0.0;
    return out;
}

FitAssessment assess_fit(const CurrentMap& map, const Box& box, const Eigen::VectorXd& theta,
                         const std::vector<Eigen::VectorXd>& reached) {
    FitAssessment out;
    out.errors = current_errors(map, theta);
    out.f = out.errors.rms * out.errors.rms * static_cast<double>(map.points());
    const std::vector<std::string> names = parameter_names(map.model());
    for (Eigen::Index j = 0; j < theta.size(); ++j)
        out.free_parameters += on_bound(box, j, theta[j]) ? 0 : 1;
    const Eigen::Index dof = 2 * map.points() - out.free_parameters;
    const double sigma2 =
        dof > 0 ? out.f / static_cast<double>(dof) : std::numeric_limits<double>::quiet_NaN();
    out.residual_sigma = std::sqrt(sigma2);
    const FreeFit fit = free_fit(map, box, theta, sigma2);
    out.condition_number = fit.condition;
    for (Eigen::Index j = 0; j < theta.size(); ++j) {
        ParameterAssessment a;
        a.name = names[static_cast<std::size_t>(j)];
        a.estimate = theta[j];
        for (const Eigen::VectorXd& x : reached)
            a.spread = std::max(a.spread, std::fabs(x[j] - theta[j]));
        a.on_bound = on_bound(box, j, theta[j]);
        if (a.on_bound) {
            const bool lower = on_lower_bound(box, j, theta[j]);
            a.standard_error = a.relative_error = std::numeric_limits<double>::quiet_NaN();
            a.verdict = Determination::not_determined;
            a.reason = std::string("on its ") + (lower ? "lower" : "upper") + " bound " +
                       number("%.6g", lower ? box.lower[j] : box.upper[j]) +
                       ": the fit would go further, so the box fixes it, not the map";
            out.parameters.push_back(std::move(a));
            continue;
        }
        const auto c =
            static_cast<Eigen::Index>(std::find(fit.free.begin(), fit.free.end(), j) - fit.free.begin());
        a.standard_error = std::sqrt(fit.covariance(c, c));
        a.relative_error = a.standard_error / std::fabs(theta[j]);
        for (Eigen::Index o = 0; o < fit.covariance.rows(); ++o) {
            const double r = fit.covariance(c, o) / std::sqrt(fit.covariance(c, c) * fit.covariance(o, o));
            if (o != c && std::isfinite(r) && std::fabs(r) > std::fabs(a.correlation) &&
                std::fabs(r) > reported_correlation) {
                a.correlation = r;
                a.partner = names[static_cast<std::size_t>(fit.free[static_cast<std::size_t>(o)])];
            }
        }
        judge(a, fit.weakest[c], fit.condition);
        out.parameters.push_back(std::move(a));
    }
    return out;
}

} // namespace mhb::fluxmap
