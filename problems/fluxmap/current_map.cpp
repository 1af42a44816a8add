// The current maps of current_map.hpp: four exponentials and one logarithm per point per evaluation
// of PM-SyRM (three exponentials for SyRM), by the exp and log of problems/core/vector_math.hpp
// (within 1 ulp, the same bits on every x86-64). The points are taken in blocks held in fixed-size
// arrays on the stack, so that an evaluation allocates nothing and every temporary stays in cache;
// each step is a plain loop over a block, which the compiler vectorises, and all of a block's
// powers go to one call of vector_exp.
#include "problems/fluxmap/current_map.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>

#include "problems/core/vector_math.hpp"

namespace mhb::fluxmap {
namespace {

constexpr Eigen::Index block = 64;

// log |psi|, with 0 standing for log 0. Every power of a zero flux linkage enters the currents
// multiplied by that flux linkage or its square (d^S through G_d psi_d, q^T through G_q psi_q,
// d^U q^V through q^2 in G_d and d^2 in G_q, and then G_d psi_d, G_q psi_q), so any finite power
// gives the same currents (up to the sign of a zero). log 0 = -inf would give the powers
// themselves exactly, but an exp(-inf) sends vector_exp down its one-by-one path for special
// inputs, and the i_q = 0 row of a map puts one in every block.
Eigen::ArrayXd log_of_flux(const Eigen::ArrayXd& psi) {
    const Eigen::ArrayXd magnitude = psi.abs();
    Eigen::ArrayXd log_psi(psi.size());
    vector_log(magnitude.data(), log_psi.data(), static_cast<std::size_t>(psi.size()));
    return (magnitude == 0.0).select(0.0, log_psi);
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
    log_d_ = log_of_flux(map_.psi_d);
    log_q_ = log_of_flux(map_.psi_q);
    d2_ = map_.psi_d.square();
    q2_ = map_.psi_q.square();
}

namespace {

// exponent * log x into out[0, n): the argument of x^exponent = exp(exponent log x), 0 for a zero
// exponent so that x^0 = 1 also where x = 0 (log x = -inf, and 0 (-inf) would be NaN). The map's
// log d and log q are finite (log_of_flux); log s^2 is -inf where s = 0.
void power_argument(const double* log_x, double exponent, Eigen::Index n, double* out) {
    if (exponent == 0.0) {
        std::fill(out, out + n, 0.0);
        return;
    }
    for (Eigen::Index j = 0; j < n; ++j)
        out[j] = exponent * log_x[j];
}

} // namespace

// A block's temporaries: exponent arguments, then their powers, n apiece (d^S, q^T, d^U q^V
// [, s^W]), and PM-SyRM's psi_b, s^2 and log s^2. Held by the caller, on its stack.
struct CurrentMap::BlockScratch {
    double argument[4 * block];
    double power[4 * block];
    double psi_b[block];
    double s2[block];
    double log_s2[block];
};

// The model's currents of points [k, k + n), n <= block, into i_d[0, n) and i_q[0, n).
void CurrentMap::block_currents(const Eigen::VectorXd& t, Eigen::Index k, Eigen::Index n, double* i_d,
                                double* i_q, BlockScratch& scratch) const {
    const double* psi_d = map_.psi_d.data() + k;
    const double* psi_q = map_.psi_q.data() + k;
    const double* log_d = log_d_.data() + k;
    const double* log_q = log_q_.data() + k;
    const double* d2 = d2_.data() + k;
    const double* q2 = q2_.data() + k;
    const bool pm = model_ == Model::pmsyrm;
    double* argument = scratch.argument;
    double* power = scratch.power;
    double* psi_b = scratch.psi_b;
    if (pm) {
        const double psi_n = t[9], k_q = t[13];
        double* s2 = scratch.s2;
        double* log_s2 = scratch.log_s2;
        for (Eigen::Index j = 0; j < n; ++j) {
            psi_b[j] = psi_d[j] - psi_n;
            s2[j] = psi_b[j] * psi_b[j] + k_q * q2[j];
        }
        vector_log(s2, log_s2, static_cast<std::size_t>(n));
        power_argument(log_s2, 0.5 * t[12], n, argument + 3 * n); // s^W = (s^2)^(W/2)
    }
    power_argument(log_d, t[5], n, argument);
    power_argument(log_q, t[6], n, argument + n);
    // d^U q^V as one exp(U log d + V log q) rather than a product of two powers: one
    // transcendental less per point.
    const double u = t[7], v = t[8];
    for (Eigen::Index j = 0; j < n; ++j)
        argument[2 * n + j] = u * log_d[j] + v * log_q[j];
    vector_exp(argument, power, static_cast<std::size_t>((pm ? 4 : 3) * n));

    // Parameters as locals: read through theta inside the loops, they could alias i_d and i_q, and
    // the loops would not be vectorised.
    const double a_d0 = t[0], a_dd = t[1], a_q0 = t[2], a_qq = t[3];
    const double dq_d = t[4] / (t[8] + 2), dq_q = t[4] / (t[7] + 2);
    const double* d_s = power;
    const double* q_t = power + n;
    const double* cross = power + 2 * n;
    for (Eigen::Index j = 0; j < n; ++j) {
        const double g_d = a_d0 + a_dd * d_s[j] + dq_d * cross[j] * q2[j];
        const double g_q = a_q0 + a_qq * q_t[j] + dq_q * cross[j] * d2[j];
        i_d[j] = g_d * psi_d[j];
        i_q[j] = g_q * psi_q[j];
    }
    if (!pm)
        return;
    const double a_b = t[10], a_bp = t[11], k_q = t[13];
    const double* s_w = power + 3 * n;
    for (Eigen::Index j = 0; j < n; ++j) {
        const double g_b = a_b * s_w[j] / (1.0 + a_bp * s_w[j]);
        i_d[j] += g_b * psi_b[j];
        i_q[j] += k_q * g_b * psi_q[j];
    }
}

void CurrentMap::currents(const Eigen::VectorXd& theta, Eigen::ArrayXd& i_d, Eigen::ArrayXd& i_q) const {
    if (theta.size() != parameter_count(model_))
        throw std::logic_error("fluxmap: a parameter vector of the wrong size");
    const Eigen::Index n = points();
    i_d.resize(n);
    i_q.resize(n);
    BlockScratch scratch;
    for (Eigen::Index k = 0; k < n; k += block)
        block_currents(theta, k, std::min(block, n - k), i_d.data() + k, i_q.data() + k, scratch);
}

void CurrentMap::residuals(const Eigen::VectorXd& theta, Eigen::VectorXd& r) const {
    Eigen::ArrayXd i_d, i_q;
    currents(theta, i_d, i_q);
    const Eigen::Index n = points();
    r.resize(2 * n);
    r.head(n) = (i_d - map_.i_d).matrix();
    r.tail(n) = (i_q - map_.i_q).matrix();
}

// The squares are summed per position in a block, then the block's partial sums pairwise: a fixed
// order (so the same bits every run), vectorisable, and more accurate than one running sum.
double CurrentMap::sum_of_squares(const Eigen::VectorXd& theta) const {
    if (theta.size() != parameter_count(model_))
        throw std::logic_error("fluxmap: a parameter vector of the wrong size");
    const Eigen::Index n = points();
    double partial[block] = {};
    double i_d[block], i_q[block];
    BlockScratch scratch;
    for (Eigen::Index k = 0; k < n; k += block) {
        const Eigen::Index m = std::min(block, n - k);
        block_currents(theta, k, m, i_d, i_q, scratch);
        const double* measured_d = map_.i_d.data() + k;
        const double* measured_q = map_.i_q.data() + k;
        for (Eigen::Index j = 0; j < m; ++j) {
            const double e_d = i_d[j] - measured_d[j];
            const double e_q = i_q[j] - measured_q[j];
            partial[j] += e_d * e_d + e_q * e_q;
        }
    }
    for (Eigen::Index width = block / 2; width > 0; width /= 2)
        for (Eigen::Index j = 0; j < width; ++j)
            partial[j] += partial[j + width];
    return partial[0];
}

} // namespace mhb::fluxmap
