// The two current-map models fitted to a flux map, evaluated at the map's measured flux linkages,
// and the least-squares objective f(theta) = sum over points of (i_d,model - i_d)^2 +
// (i_q,model - i_q)^2, in A^2. With d = |psi_d|, q = |psi_q|:
//   SyRM (Hinkkanen et al. 2017), theta = a_d0 a_dd a_q0 a_qq a_dq S T U V:
//     G_d = a_d0 + a_dd d^S + a_dq/(V+2) d^U q^(V+2),  G_q = a_q0 + a_qq q^T + a_dq/(U+2) d^(U+2) q^V,
//     i_d = G_d psi_d,  i_q = G_q psi_q;
//   PM-SyRM (Lelli et al. 2024), theta = those nine, psi_n a_b a_bp W k_q: psi_b = psi_d - psi_n,
//     s = sqrt(psi_b^2 + k_q psi_q^2), G_b = a_b s^W / (1 + a_bp s^W), i_d += G_b psi_b,
//     i_q += k_q G_b psi_q.
// The points are fixed, so log d and log q are taken once; each power is then exp(p log x), by the
// array exp and log of problems/core/vector_math.hpp. x^0 is 1 also at x = 0 (psi_q = 0 on the
// i_q = 0 row), and a power of a zero flux linkage, always multiplied by it, gives a zero current.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "problems/fluxmap/flux_map.hpp"

namespace mhb::fluxmap {

enum class Model { syrm, pmsyrm };

// 9 or 14.
Eigen::Index parameter_count(Model model);
// a_d0 a_dd a_q0 a_qq a_dq S T U V [psi_n a_b a_bp W k_q].
std::vector<std::string> parameter_names(Model model);
// Indices of the exponents (S T U V [W]): they must stay >= 0, since 0^p is infinite for p < 0.
std::vector<Eigen::Index> exponent_indices(Model model);

class CurrentMap {
public:
    CurrentMap(Model model, FluxMap map);

    [[nodiscard]] Model model() const { return model_; }
    [[nodiscard]] const FluxMap& map() const { return map_; }
    [[nodiscard]] Eigen::Index points() const { return map_.size(); }

    // The model's currents at every point.
    void currents(const Eigen::VectorXd& theta, Eigen::ArrayXd& i_d, Eigen::ArrayXd& i_q) const;
    // r = [i_d,model - i_d; i_q,model - i_q] (2 x points entries).
    void residuals(const Eigen::VectorXd& theta, Eigen::VectorXd& r) const;
    // f(theta), A^2. Thread-safe; allocates nothing.
    [[nodiscard]] double sum_of_squares(const Eigen::VectorXd& theta) const;

private:
    struct BlockScratch;
    // The currents of points [k, k + n), n at most 64 (one block), into i_d[0, n), i_q[0, n).
    void block_currents(const Eigen::VectorXd& t, Eigen::Index k, Eigen::Index n, double* i_d, double* i_q,
                        BlockScratch& scratch) const;

    Model model_;
    FluxMap map_;
    Eigen::ArrayXd log_d_, log_q_, d2_, q2_;
};

} // namespace mhb::fluxmap
