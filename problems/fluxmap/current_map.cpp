// The current maps of current_map.hpp: four exponentials and one logarithm per point per evaluation
// of PM-SyRM (three exponentials for SyRM). The sum of squares runs over blocks of points held in
// fixed-size arrays on the stack, so that an evaluation allocates nothing and every temporary
// stays in cache.
#include "problems/fluxmap/current_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace mhb::fluxmap {
namespace {

constexpr Eigen::Index block = 64;
using Block = Eigen::Array<double, Eigen::Dynamic, 1, 0, block, 1>;

// x^p from log x: exp(p log x), with x^0 = 1 even where x = 0 (log x = -inf).
template <class LogArray> Block power(const LogArray& log_x, double p) {
    if (p == 0.0)
        return Block::Ones(log_x.size());
    return (p * log_x).exp();
}

// d^U q^V as one exp(U log d + V log q) rather than a product of two: one transcendental less per
// point. A zero exponent drops its term, so that 0^0 = 1 holds here too.
template <class LogD, class LogQ>
Block cross_power(const LogD& log_d, double u, const LogQ& log_q, double v) {
    if (u == 0.0)
        return power(log_q, v);
    if (v == 0.0)
        return power(log_d, u);
    return (u * log_d + v * log_q).exp();
}

} // namespace

Eigen::Index parameter_count(Model model) {
    return model == Model::syrm ? 9 : 14;
}

std::vector<std::string> parameter_names(Model model) {
    std::vector<std::string> names = {"a_d0", "a_dd", "a_q0", "a_qq", "a_dq", "S", "T", "U", "V"};
    if (model == Model::pmsyrm)
        names.insert(names.end(), {"psi_n", "a_b", "a_bp", "W", "k_q"});
    return names;
}

std::vector<Eigen::Index> exponent_indices(Model model) {
    std::vector<Eigen::Index> e = {5, 6, 7, 8};
    if (model == Model::pmsyrm)
        e.push_back(12);
    return e;
}

CurrentMap::CurrentMap(Model model, FluxMap map) : model_(model), map_(std::move(map)) {
    log_d_ = map_.psi_d.abs().log();
    log_q_ = map_.psi_q.abs().log();
    d2_ = map_.psi_d.square();
    q2_ = map_.psi_q.square();
}

namespace {

// The model's currents of points [k, k + n) into `i_d`, `i_q`.
struct BlockModel {
    const FluxMap& map;
    const Eigen::ArrayXd& log_d;
    const Eigen::ArrayXd& log_q;
    const Eigen::ArrayXd& d2;
    const Eigen::ArrayXd& q2;

    void operator()(const Eigen::VectorXd& t, bool pm, Eigen::Index k, Eigen::Index n, Block& i_d,
                    Block& i_q) const {
        const auto psi_d = map.psi_d.segment(k, n);
        const auto psi_q = map.psi_q.segment(k, n);
        const Block cross = cross_power(log_d.segment(k, n), t[7], log_q.segment(k, n), t[8]); // d^U q^V
        const Block g_d =
            t[0] + t[1] * power(log_d.segment(k, n), t[5]) + t[4] / (t[8] + 2) * cross * q2.segment(k, n);
        const Block g_q =
            t[2] + t[3] * power(log_q.segment(k, n), t[6]) + t[4] / (t[7] + 2) * cross * d2.segment(k, n);
        i_d = g_d * psi_d;
        i_q = g_q * psi_q;
        if (!pm)
            return;
        const Block psi_b = psi_d - t[9];
        const Block s2 = psi_b.square() + t[13] * q2.segment(k, n);
        const Block sW = power(s2.log(), 0.5 * t[12]); // s^W = (s^2)^(W/2)
        const Block g_b = t[10] * sW / (1.0 + t[11] * sW);
        i_d += g_b * psi_b;
        i_q += t[13] * g_b * psi_q;
    }
};

} // namespace

void CurrentMap::currents(const Eigen::VectorXd& theta, Eigen::ArrayXd& i_d, Eigen::ArrayXd& i_q) const {
    if (theta.size() != parameter_count(model_))
        throw std::logic_error("fluxmap: a parameter vector of the wrong size");
    const BlockModel at{map_, log_d_, log_q_, d2_, q2_};
    const Eigen::Index n = points();
    i_d.resize(n);
    i_q.resize(n);
    Block bd, bq;
    for (Eigen::Index k = 0; k < n; k += block) {
        const Eigen::Index m = std::min(block, n - k);
        at(theta, model_ == Model::pmsyrm, k, m, bd, bq);
        i_d.segment(k, m) = bd;
        i_q.segment(k, m) = bq;
    }
}

void CurrentMap::residuals(const Eigen::VectorXd& theta, Eigen::VectorXd& r) const {
    Eigen::ArrayXd i_d, i_q;
    currents(theta, i_d, i_q);
    const Eigen::Index n = points();
    r.resize(2 * n);
    r.head(n) = (i_d - map_.i_d).matrix();
    r.tail(n) = (i_q - map_.i_q).matrix();
}

double CurrentMap::sum_of_squares(const Eigen::VectorXd& theta) const {
    if (theta.size() != parameter_count(model_))
        throw std::logic_error("fluxmap: a parameter vector of the wrong size");
    const BlockModel at{map_, log_d_, log_q_, d2_, q2_};
    const Eigen::Index n = points();
    Block bd, bq;
    double sum = 0.0;
    for (Eigen::Index k = 0; k < n; k += block) {
        const Eigen::Index m = std::min(block, n - k);
        at(theta, model_ == Model::pmsyrm, k, m, bd, bq);
        sum += (bd - map_.i_d.segment(k, m)).square().sum() + (bq - map_.i_q.segment(k, m)).square().sum();
    }
    return sum;
}

} // namespace mhb::fluxmap
