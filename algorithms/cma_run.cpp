// One CMA-ES run (cma_run.hpp). Hansen's tutorial (arXiv:1604.00772), Table 1 and Appendix A, with
// positive weights only; coordinates normalised to the unit box, y = (x - lower) / (upper - lower).
//
// Linear algebra per generation, in place in buffers sized once per run (no allocation in the
// loop): the lambda steps are one product B (D Z) of the n x n eigenbasis with the n x lambda
// normal draws; the weighted mean step and the rank-mu update are products with the n x mu matrix
// of the selected steps. The eigendecomposition of C, O(n^3), is the run's largest cost; it is
// postponed by Hansen's rule in purecma.py, the minimal CMA-ES shipped with pycma: after at least
// 0.5 lambda / (n (c_1 + c_mu)) evaluations since the last one ("0.5 is chosen such that eig takes
// 2 times the time of tell in >= 20-D"), which keeps the cost per evaluation O(n^2) at every D.
// (The tutorial's rule, which pycma's CMAEvolutionStrategy keeps, every max(1, 1 / (10 n (c_1 +
// c_mu))) generations, decomposes at every generation from about D = 10 on: five times as often.)
#include "algorithms/cma_run.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "algorithms/symmetric_eigensolver.hpp"

namespace mhb::cma {

// The constants of a run of population lambda in dimension n (tutorial, Table 1).
struct CmaConstants {
    CmaConstants(Eigen::Index n, int lambda_) : lambda(lambda_), mu(lambda_ / 2), weights(mu) {
        dn = static_cast<double>(n);
        for (int i = 0; i < mu; ++i)
            weights[i] = std::log((lambda + 1) / 2.0) - std::log(i + 1.0);
        weights /= weights.sum();
        mu_eff = 1.0 / weights.squaredNorm();
        c_c = (4.0 + mu_eff / dn) / (dn + 4.0 + 2.0 * mu_eff / dn);
        c_s = (mu_eff + 2.0) / (dn + mu_eff + 5.0);
        c_1 = 2.0 / ((dn + 1.3) * (dn + 1.3) + mu_eff);
        c_mu = std::min(1.0 - c_1, 2.0 * (mu_eff - 2.0 + 1.0 / mu_eff) / ((dn + 2.0) * (dn + 2.0) + mu_eff));
        d_s = 1.0 + 2.0 * std::max(0.0, std::sqrt((mu_eff - 1.0) / (dn + 1.0)) - 1.0) + c_s;
        chi_n = std::sqrt(dn) * (1.0 - 1.0 / (4.0 * dn) + 1.0 / (21.0 * dn * dn));
        eigen_gap_evaluations = 0.5 * lambda / (dn * (c_1 + c_mu));
    }
    int lambda, mu;
    Eigen::VectorXd weights;
    double dn, mu_eff, c_c, c_s, c_1, c_mu, d_s, chi_n, eigen_gap_evaluations;
};

class CmaRunState {
public:
    CmaRunState(const Objective& objective, const RunSettings& settings, double tol_x_sigma0, Rng& rng)
        : k_(objective.dimension(), settings.lambda), box_(objective.bounds()),
          width_((box_.upper - box_.lower).array()), n_(objective.dimension()), sigma_(settings.sigma0),
          tol_x_(1e-12 * tol_x_sigma0), max_generations_(settings.max_generations),
          history_length_(static_cast<std::size_t>(10 + std::ceil(30.0 * k_.dn / k_.lambda))) {
        m_.resize(n_);
        for (Eigen::Index i = 0; i < n_; ++i)
            m_[i] = rng.uniform();
        p_s_.setZero(n_);
        p_c_.setZero(n_);
        c_.setIdentity(n_, n_);
        b_.setIdentity(n_, n_);
        diag_d_.setOnes(n_);
        whitened_.resize(n_);
        z_.resize(n_, k_.lambda);
        steps_.resize(n_, k_.lambda);
        selected_.resize(n_, k_.mu);
        weighted_selected_.resize(n_, k_.mu);
        y_w_.resize(n_);
        candidate_.resize(n_);
        redrawn_.resize(n_);
        x_.assign(static_cast<std::size_t>(k_.lambda), Eigen::VectorXd::Zero(n_));
        f_.resize(static_cast<std::size_t>(k_.lambda));
        order_.resize(static_cast<std::size_t>(k_.lambda));
    }

    // Samples, evaluates (as one batch) and adapts one generation; false once the run should stop.
    bool generation(Objective& objective, Rng& rng, bool& first) {
        sample(rng);
        objective.evaluate_batch(x_, f_); // clamps the samples still outside
        if (first) {
            objective.initialised();
            first = false;
        } else {
            objective.end_iteration();
        }
        ++generation_;
        evaluations_ += k_.lambda;
        record_steps();
        rank_offspring();
        const bool h_s = update_mean_and_paths();
        update_covariance_and_step_size(h_s);
        if (static_cast<double>(evaluations_) > eigen_updated_at_ + k_.eigen_gap_evaluations)
            update_eigensystem();
        return !should_stop();
    }

private:
    // x_j = m + sigma B D z_j in the unit box, mapped to the problem's box. A sample outside the
    // box is redrawn up to 9 more times (the draws cost no evaluation); the Objective clamps one
    // still outside.
    void sample(Rng& rng) {
        for (Eigen::Index j = 0; j < k_.lambda; ++j)
            for (Eigen::Index i = 0; i < n_; ++i)
                z_(i, j) = rng.normal();
        z_ = diag_d_.asDiagonal() * z_;
        steps_.noalias() = b_ * z_;
        for (int j = 0; j < k_.lambda; ++j) {
            candidate_ = m_ + sigma_ * steps_.col(j);
            for (int attempt = 1; attempt < 10 && !inside_unit_box(candidate_); ++attempt)
                redraw(rng);
            x_[static_cast<std::size_t>(j)] = box_.lower + (candidate_.array() * width_).matrix();
        }
    }

    void redraw(Rng& rng) {
        for (Eigen::Index i = 0; i < n_; ++i)
            redrawn_[i] = diag_d_[i] * rng.normal();
        candidate_.noalias() = m_ + sigma_ * (b_ * redrawn_);
    }

    static bool inside_unit_box(const Eigen::VectorXd& y) {
        return (y.array() >= 0.0).all() && (y.array() <= 1.0).all();
    }

    // The steps (x - m) / sigma of the points actually evaluated, in normalised coordinates.
    void record_steps() {
        for (int j = 0; j < k_.lambda; ++j) {
            steps_.col(j) = ((x_[static_cast<std::size_t>(j)] - box_.lower).array() / width_).matrix() - m_;
            steps_.col(j) /= sigma_;
        }
    }

    void rank_offspring() {
        std::iota(order_.begin(), order_.end(), 0);
        std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) {
            return f_[static_cast<std::size_t>(a)] < f_[static_cast<std::size_t>(b)];
        });
        best_history_.push_back(f_[static_cast<std::size_t>(order_[0])]);
        if (best_history_.size() > history_length_)
            best_history_.pop_front();
        for (int i = 0; i < k_.mu; ++i) {
            selected_.col(i) = steps_.col(order_[static_cast<std::size_t>(i)]);
            weighted_selected_.col(i) = k_.weights[i] * selected_.col(i);
        }
    }

    // m += sigma y_w; the evolution paths p_s and p_c. Returns h_sigma.
    bool update_mean_and_paths() {
        y_w_.noalias() = selected_ * k_.weights;
        m_ += sigma_ * y_w_;
        p_s_ = (1.0 - k_.c_s) * p_s_;
        // C^(-1/2) y_w = B D^-1 B^T y_w as two matrix-vector products: O(n^2), where forming
        // C^(-1/2) at each eigendecomposition would cost a matrix product, O(n^3).
        whitened_.noalias() = b_.transpose() * y_w_;
        whitened_.array() /= diag_d_.array();
        p_s_.noalias() += std::sqrt(k_.c_s * (2.0 - k_.c_s) * k_.mu_eff) * (b_ * whitened_);
        ps_norm_ = p_s_.norm();
        const double h_s_threshold =
            (1.4 + 2.0 / (k_.dn + 1.0)) * k_.chi_n *
            std::sqrt(1.0 - std::pow(1.0 - k_.c_s, 2.0 * static_cast<double>(generation_)));
        const bool h_s = ps_norm_ < h_s_threshold;
        p_c_ = (1.0 - k_.c_c) * p_c_ + (h_s ? std::sqrt(k_.c_c * (2.0 - k_.c_c) * k_.mu_eff) : 0.0) * y_w_;
        return h_s;
    }

    void update_covariance_and_step_size(bool h_s) {
        const double delta_h = h_s ? 0.0 : k_.c_c * (2.0 - k_.c_c);
        c_ *= 1.0 + k_.c_1 * delta_h - k_.c_1 - k_.c_mu;
        c_.noalias() += k_.c_1 * (p_c_ * p_c_.transpose());
        c_.noalias() += k_.c_mu * (weighted_selected_ * selected_.transpose());
        sigma_ *= std::exp((k_.c_s / k_.d_s) * (ps_norm_ / k_.chi_n - 1.0));
    }

    void update_eigensystem() {
        c_ = 0.5 * (c_ + c_.transpose()).eval();
        solver_.compute(c_);
        b_ = solver_.eigenvectors();
        diag_d_ = solver_.eigenvalues().cwiseMax(1e-300).cwiseSqrt();
        eigen_updated_at_ = static_cast<double>(evaluations_);
    }

    // Hansen's tutorial, appendix B.3, and pycma's defaults: TolFun 1e-12 on the range of the
    // current and the last 10 + ceil(30 D / lambda) generations' best f, TolX, condition number of
    // C above 1e14, no effect of an axis or of a coordinate, a non-finite or huge sigma, the cap.
    bool should_stop() const {
        const auto [lo_f, hi_f] = std::minmax_element(f_.begin(), f_.end());
        const auto [lo_h, hi_h] = std::minmax_element(best_history_.begin(), best_history_.end());
        const bool tol_fun = best_history_.size() == history_length_ &&
                             std::max(*hi_f, *hi_h) - std::min(*lo_f, *lo_h) < 1e-12;
        const bool tol_x = (sigma_ * p_c_.cwiseAbs().array() < tol_x_).all() &&
                           (sigma_ * c_.diagonal().cwiseSqrt().array() < tol_x_).all();
        const bool ill_conditioned = diag_d_.maxCoeff() > 1e7 * diag_d_.minCoeff();
        const auto axis = static_cast<Eigen::Index>(generation_ % n_);
        const double axis_step = 0.1 * sigma_ * diag_d_[axis];
        bool no_effect_axis = true, no_effect_coord = false;
        for (Eigen::Index i = 0; i < n_; ++i) {
            no_effect_axis = no_effect_axis && m_[i] + axis_step * b_(i, axis) == m_[i];
            no_effect_coord = no_effect_coord || m_[i] + 0.2 * sigma_ * std::sqrt(c_(i, i)) == m_[i];
        }
        return tol_fun || tol_x || ill_conditioned || no_effect_axis || no_effect_coord ||
               !std::isfinite(sigma_) || sigma_ > 1e6 || generation_ >= max_generations_;
    }

    CmaConstants k_;
    const Box& box_;
    Eigen::ArrayXd width_;
    Eigen::Index n_;
    double sigma_, tol_x_, ps_norm_ = 0.0;
    long long max_generations_, generation_ = 0;
    std::int64_t evaluations_ = 0;
    double eigen_updated_at_ = 0.0;
    std::size_t history_length_;
    std::deque<double> best_history_;

    Eigen::VectorXd m_, p_s_, p_c_, diag_d_, y_w_, candidate_, redrawn_;
    Eigen::MatrixXd c_, b_;
    Eigen::VectorXd whitened_;                     // D^-1 B^T y_w
    Eigen::MatrixXd z_, steps_;                    // n x lambda
    Eigen::MatrixXd selected_, weighted_selected_; // n x mu: the best steps, and times their weights
    SymmetricEigensolver solver_{};                // Eigen's SelfAdjointEigenSolver, bit for bit, faster
    std::vector<Eigen::VectorXd> x_;
    std::vector<double> f_;
    std::vector<int> order_;
};

void run_once(Objective& objective, Rng& rng, const RunSettings& settings, double tol_x_sigma0, bool& first) {
    CmaRunState state(objective, settings, tol_x_sigma0, rng);
    while (!objective.exhausted() && state.generation(objective, rng, first)) {
    }
}

} // namespace mhb::cma
