// The curves of fitted_curves.hpp: all points of all curves solved at once, each Newton step a
// CurrentMap over the current guesses (the model's own evaluation, so that the curves are exactly
// the fitted model) and a forward-difference 2 x 2 Jacobian per point.
#include "problems/fluxmap/fitted_curves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace mhb::fluxmap {
namespace {

constexpr int newton_iterations = 100;
constexpr double converged_current = 1e-6; // A: a point further off than this is dropped
constexpr double largest_step = 0.05;      // V s per Newton step, so that no step jumps a knee
constexpr double flux_difference = 1e-7;   // V s, the forward-difference step

// The model's currents at the flux linkages (psi_d, psi_q).
void model_currents(Model model, const Eigen::VectorXd& theta, const Eigen::ArrayXd& psi_d,
                    const Eigen::ArrayXd& psi_q, Eigen::ArrayXd& i_d, Eigen::ArrayXd& i_q) {
    FluxMap at;
    at.psi_d = psi_d;
    at.psi_q = psi_q;
    at.i_d = at.i_q = Eigen::ArrayXd::Zero(psi_d.size());
    CurrentMap(model, std::move(at)).currents(theta, i_d, i_q);
}

// Starting guesses: the flux linkages of the measured point nearest to each wanted current pair
// (currents scaled by the map's ranges).
void nearest_measured(const FluxMap& map, const Eigen::ArrayXd& i_d, const Eigen::ArrayXd& i_q,
                      Eigen::ArrayXd& psi_d, Eigen::ArrayXd& psi_q) {
    const double sd = std::max(map.i_d.maxCoeff() - map.i_d.minCoeff(), 1e-12);
    const double sq = std::max(map.i_q.maxCoeff() - map.i_q.minCoeff(), 1e-12);
    psi_d.resize(i_d.size());
    psi_q.resize(i_d.size());
    for (Eigen::Index k = 0; k < i_d.size(); ++k) {
        Eigen::Index best = 0;
        (((map.i_d - i_d[k]) / sd).square() + ((map.i_q - i_q[k]) / sq).square()).minCoeff(&best);
        psi_d[k] = map.psi_d[best];
        psi_q[k] = map.psi_q[best];
    }
}

// Newton's method on i(psi) = (i_d, i_q) for every point at once; unconverged points become NaN.
void solve_flux(const CurrentMap& map, const Eigen::VectorXd& theta, const Eigen::ArrayXd& i_d,
                const Eigen::ArrayXd& i_q, Eigen::ArrayXd& psi_d, Eigen::ArrayXd& psi_q) {
    const Model model = map.model();
    nearest_measured(map.map(), i_d, i_q, psi_d, psi_q);
    Eigen::ArrayXd md, mq, dd_d, dq_d, dd_q, dq_q;
    for (int it = 0; it < newton_iterations; ++it) {
        model_currents(model, theta, psi_d, psi_q, md, mq);
        const Eigen::ArrayXd rd = md - i_d, rq = mq - i_q;
        if ((rd.abs().max(rq.abs()) <= converged_current * 1e-3).all())
            break;
        model_currents(model, theta, psi_d + flux_difference, psi_q, dd_d, dq_d);
        model_currents(model, theta, psi_d, psi_q + flux_difference, dd_q, dq_q);
        // J = [di_d/dpsi_d di_d/dpsi_q; di_q/dpsi_d di_q/dpsi_q], step = -J^-1 r.
        const Eigen::ArrayXd a = (dd_d - md) / flux_difference, b = (dd_q - md) / flux_difference;
        const Eigen::ArrayXd c = (dq_d - mq) / flux_difference, d = (dq_q - mq) / flux_difference;
        const Eigen::ArrayXd det = a * d - b * c;
        const Eigen::ArrayXd step_d = -(d * rd - b * rq) / det, step_q = -(a * rq - c * rd) / det;
        psi_d += step_d.unaryExpr(
            [](double s) { return std::isfinite(s) ? std::clamp(s, -largest_step, largest_step) : 0.0; });
        psi_q += step_q.unaryExpr(
            [](double s) { return std::isfinite(s) ? std::clamp(s, -largest_step, largest_step) : 0.0; });
    }
    model_currents(model, theta, psi_d, psi_q, md, mq);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (Eigen::Index k = 0; k < psi_d.size(); ++k)
        if (!(std::fabs(md[k] - i_d[k]) <= converged_current &&
              std::fabs(mq[k] - i_q[k]) <= converged_current))
            psi_d[k] = psi_q[k] = nan;
}

} // namespace

std::vector<double> curve_levels(const Eigen::ArrayXd& values, int count, bool non_negative) {
    std::set<double> distinct;
    for (const double v : values)
        if (!non_negative || v >= 0)
            distinct.insert(v + 0.0); // -0 is 0: a level is named "0 A", never "-0 A"
    if (distinct.empty() || count < 1)
        return {};
    const std::vector<double> sorted(distinct.begin(), distinct.end());
    const auto n = static_cast<int>(sorted.size());
    std::vector<double> out;
    for (int k = 0; k < count; ++k) {
        const double t = count == 1 ? 0.0 : static_cast<double>(k) / (count - 1);
        if (n > 60) // not a grid: evenly over the range
            out.push_back(sorted.front() + t * (sorted.back() - sorted.front()));
        else
            out.push_back(sorted[static_cast<std::size_t>(std::lround(t * (n - 1)))]);
    }
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<FluxCurve> fitted_curves(const CurrentMap& map, const Eigen::VectorXd& theta,
                                     const std::vector<double>& q_levels, const std::vector<double>& d_levels,
                                     int samples) {
    const FluxMap& data = map.map();
    std::vector<FluxCurve> curves;
    for (const bool d_axis : {true, false})
        for (const double level : d_axis ? q_levels : d_levels) {
            const Eigen::ArrayXd& swept = d_axis ? data.i_d : data.i_q;
            FluxCurve curve;
            curve.d_axis = d_axis;
            curve.level = level;
            const Eigen::ArrayXd sweep =
                Eigen::ArrayXd::LinSpaced(samples, swept.minCoeff(), swept.maxCoeff());
            curve.i_d = d_axis ? sweep : Eigen::ArrayXd::Constant(samples, level);
            curve.i_q = d_axis ? Eigen::ArrayXd::Constant(samples, level) : sweep;
            curves.push_back(std::move(curve));
        }
    // Every point of every curve in one system.
    Eigen::Index total = 0;
    for (const FluxCurve& c : curves)
        total += c.i_d.size();
    Eigen::ArrayXd i_d(total), i_q(total), psi_d, psi_q;
    Eigen::Index at = 0;
    for (const FluxCurve& c : curves) {
        i_d.segment(at, c.i_d.size()) = c.i_d;
        i_q.segment(at, c.i_d.size()) = c.i_q;
        at += c.i_d.size();
    }
    if (total > 0)
        solve_flux(map, theta, i_d, i_q, psi_d, psi_q);
    at = 0;
    for (FluxCurve& c : curves) {
        c.psi_d = psi_d.segment(at, c.i_d.size());
        c.psi_q = psi_q.segment(at, c.i_d.size());
        at += c.i_d.size();
    }
    return curves;
}

} // namespace mhb::fluxmap
