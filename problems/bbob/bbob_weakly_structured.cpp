// BBOB multi-modal functions with weak global structure f20-f24: Schwefel x sin(sqrt|x|),
// Gallagher's Gaussian 101-me and 21-hi peaks, Katsuura, Lunacek bi-Rastrigin.
// Definitions: Hansen et al. (2009), checked against COCO's f_schwefel.c (with
// transform_vars_x_hat.c and transform_vars_z_hat.c), f_gallagher.c, f_katsuura.c and
// f_lunacek_bi_rastrigin.c.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/bbob/bbob_function.hpp"
#include "problems/bbob/bbob_random.hpp"
#include "problems/bbob/bbob_transforms.hpp"

namespace mhb::bbob {
namespace {

// f20: -1/(100 D) sum z_i sin(sqrt|z_i|) + 4.189828872724339 + 100 f_pen(z/100), with
// x_hat = 2 (1+-) x, z_hat_1 = x_hat_1, z_hat_{i+1} = x_hat_{i+1} + 0.25 (x_hat_i - 2|x_opt_i|),
// z = 100 (Lambda^10 (z_hat - 2|x_opt|) + 2|x_opt|), x_opt = 4.2096874637/2 (1+-).
class Schwefel final : public Function {
public:
    explicit Schwefel(const InstanceSetup& s)
        : signs_(s.dimension), xopt_(s.dimension), scales_(lambda_diagonal(10.0, s.dimension)),
          fopt_(s.f_opt) {
        const std::vector<double> u = legacy_uniform(static_cast<std::size_t>(s.dimension), s.rseed);
        for (Eigen::Index i = 0; i < s.dimension; ++i) {
            signs_[i] = u[static_cast<std::size_t>(i)] - 0.5 < 0.0 ? -1.0 : 1.0;
            xopt_[i] = 0.5 * 4.2096874637 * signs_[i];
        }
        twice_abs_xopt_ = 2.0 * xopt_.cwiseAbs();
    }
    double value(const Eigen::VectorXd& x) const override {
        const Eigen::Index n = x.size();
        SmallVector x_hat(n);
        for (Eigen::Index i = 0; i < n; ++i)
            x_hat[i] = 2.0 * (signs_[i] * x[i]);
        SmallVector z(n);
        z[0] = x_hat[0];
        for (Eigen::Index i = 1; i < n; ++i)
            z[i] = x_hat[i] + 0.25 * (x_hat[i - 1] - twice_abs_xopt_[i - 1]);
        for (Eigen::Index i = 0; i < n; ++i)
            z[i] = 100.0 * (scales_[i] * (z[i] - twice_abs_xopt_[i]) + twice_abs_xopt_[i]);
        double penalty = 0.0;
        double sum = 0.0;
        for (Eigen::Index i = 0; i < n; ++i) {
            const double excess = std::fabs(z[i]) - 500.0;
            if (excess > 0.0)
                penalty += excess * excess;
            sum += z[i] * std::sin(std::sqrt(std::fabs(z[i])));
        }
        return 0.01 * (penalty + 418.9828872724339 - sum / static_cast<double>(n)) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd signs_;
    Eigen::VectorXd xopt_;
    Eigen::VectorXd twice_abs_xopt_;
    Eigen::VectorXd scales_;
    double fopt_;
};

// A value with its index, to turn uniform draws into a permutation as the legacy code does
// (sorting by value; ties keep index order, where qsort leaves it unspecified, but 32-bit
// uniform draws do not tie in practice).
std::vector<std::size_t> ranks_by_value(const std::vector<double>& values, std::size_t n) {
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    return order; // order[j] = index of the j-th smallest value
}

// f21 (101 peaks) and f22 (21 peaks): T_osz(10 - max_i w_i exp(-1/(2D) (z - y_i)^T C_i (z - y_i)))^2
// + f_pen(x), z = R x, peak i at y_i (rotated) with diagonal conditioning C_i.
class Gallagher final : public Function {
public:
    Gallagher(const InstanceSetup& s, std::size_t peaks) : fopt_(s.f_opt) {
        const Eigen::Index d = s.dimension;
        const auto dn = static_cast<std::size_t>(d);
        const double max_condition = 1000.0;
        const double first_condition = peaks == 101 ? std::sqrt(max_condition) : max_condition;
        const double b = peaks == 101 ? 10.0 : 9.8;
        const double c = peaks == 101 ? 5.0 : 4.9;
        r_ = legacy_rotation(s.rseed, d);

        // Condition of each peak: a random permutation of 1000^(k/(peaks-2)); peak 0 gets the first.
        const std::vector<double> u_conditions = legacy_uniform(peaks - 1, s.rseed);
        const std::vector<std::size_t> perm = ranks_by_value(u_conditions, peaks - 1);
        std::vector<double> condition(peaks);
        condition[0] = first_condition;
        weights_.resize(static_cast<Eigen::Index>(peaks));
        weights_[0] = 10.0;
        for (std::size_t i = 1; i < peaks; ++i) {
            condition[i] =
                std::pow(max_condition, static_cast<double>(perm[i - 1]) / static_cast<double>(peaks - 2));
            weights_[static_cast<Eigen::Index>(i)] =
                static_cast<double>(i - 1) / static_cast<double>(peaks - 2) * (9.1 - 1.1) + 1.1;
        }
        // Per-peak diagonal scales: condition_i^(rank/(D-1) - 1/2), ranks from a random permutation.
        scales_.resize(d, static_cast<Eigen::Index>(peaks));
        for (std::size_t i = 0; i < peaks; ++i) {
            const std::vector<double> u = legacy_uniform(dn, s.rseed + static_cast<std::int64_t>(1000 * i));
            const std::vector<std::size_t> order = ranks_by_value(u, dn);
            for (std::size_t j = 0; j < dn; ++j)
                scales_(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) =
                    std::pow(condition[i], static_cast<double>(order[j]) / static_cast<double>(d - 1) - 0.5);
        }
        // Peak positions, uniform in [-c, b - c]^D (peak 0 shrunk by 0.8), rotated by R.
        const std::vector<double> u = legacy_uniform(dn * peaks, s.rseed);
        xopt_.resize(d);
        peaks_.resize(d, static_cast<Eigen::Index>(peaks));
        for (Eigen::Index i = 0; i < d; ++i) {
            xopt_[i] = 0.8 * (b * u[static_cast<std::size_t>(i)] - c);
            for (std::size_t j = 0; j < peaks; ++j) {
                double sum = 0.0;
                for (Eigen::Index k = 0; k < d; ++k)
                    sum += r_(i, k) * (b * u[j * dn + static_cast<std::size_t>(k)] - c);
                peaks_(i, static_cast<Eigen::Index>(j)) = j == 0 ? sum * 0.8 : sum;
            }
        }
    }
    double value(const Eigen::VectorXd& x) const override {
        const Eigen::Index d = x.size();
        const SmallVector z = r_ * x;
        const double factor = -0.5 / static_cast<double>(d);
        double best = 0.0;
        for (Eigen::Index i = 0; i < peaks_.cols(); ++i) {
            double sum = 0.0;
            for (Eigen::Index j = 0; j < d; ++j) {
                const double diff = z[j] - peaks_(j, i);
                sum += scales_(j, i) * diff * diff;
            }
            best = std::max(best, weights_[i] * std::exp(factor * sum));
        }
        const double g = t_osz(10.0 - best);
        return g * g + f_pen(x) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::MatrixXd r_;
    Eigen::MatrixXd peaks_;  // D x peaks, rotated peak positions
    Eigen::MatrixXd scales_; // D x peaks
    Eigen::VectorXd weights_;
    Eigen::VectorXd xopt_;
    double fopt_;
};

// f23: 10/D^2 prod_i (1 + i sum_{j=1}^{32} |2^j z_i - round(2^j z_i)| / 2^j)^(10/D^1.2) - 10/D^2
// + f_pen(x), z = R Lambda^100 Q (x - x_opt).
class Katsuura final : public Function {
public:
    explicit Katsuura(const InstanceSetup& s)
        : xopt_(legacy_xopt(s.rseed, s.dimension)),
          m_(rotate_scale_rotate(legacy_rotation(s.rseed + 1000000, s.dimension),
                                 sqrt_power_diagonal(100.0, s.dimension),
                                 legacy_rotation(s.rseed, s.dimension))),
          fopt_(s.f_opt) {}
    double value(const Eigen::VectorXd& x) const override {
        const SmallVector z = m_ * (x - xopt_);
        const Eigen::Index n = z.size();
        double product = 1.0;
        for (Eigen::Index i = 0; i < n; ++i) {
            double sum = 0.0;
            for (int j = 1; j < 33; ++j) {
                const double p = std::ldexp(1.0, j); // 2^j exactly
                sum += std::fabs(p * z[i] - round_half_up(p * z[i])) / p;
            }
            product *= 1.0 + (static_cast<double>(i) + 1.0) * sum;
        }
        const double d = static_cast<double>(n);
        return 10.0 / d / d * (-1.0 + std::pow(product, 10.0 / std::pow(d, 1.2))) + fopt_ + f_pen(x);
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    Eigen::MatrixXd m_;
    double fopt_;
};

// f24: min(sum (x_hat_i - mu0)^2, D + s sum (x_hat_i - mu1)^2) + 10 (D - sum cos(2 pi z_i))
// + 10^4 f_pen(x), x_hat = 2 sign(x_opt) x, z = R Lambda^100 Q (x_hat - mu0), mu0 = 2.5,
// s = 1 - 1/(2 sqrt(D + 20) - 8.2), mu1 = -sqrt((mu0^2 - 1)/s), x_opt = mu0/2 (1+-).
class LunacekBiRastrigin final : public Function {
public:
    explicit LunacekBiRastrigin(const InstanceSetup& s)
        : xopt_(s.dimension), q_(legacy_rotation(s.rseed + 1000000, s.dimension)),
          scaled_r_(legacy_rotation(s.rseed, s.dimension)), fopt_(s.f_opt) {
        const std::vector<double> g = legacy_gauss(static_cast<std::size_t>(s.dimension), s.rseed);
        for (Eigen::Index i = 0; i < s.dimension; ++i)
            xopt_[i] = g[static_cast<std::size_t>(i)] < 0.0 ? -0.5 * mu0 : 0.5 * mu0;
        for (Eigen::Index i = 0; i < s.dimension; ++i)
            scaled_r_.row(i) *=
                std::pow(std::sqrt(100.0), static_cast<double>(i) / static_cast<double>(s.dimension - 1));
        s_ = 1.0 - 0.5 / (std::sqrt(static_cast<double>(s.dimension + 20)) - 4.1);
        mu1_ = -std::sqrt((mu0 * mu0 - 1.0) / s_);
    }
    double value(const Eigen::VectorXd& x) const override {
        const Eigen::Index n = x.size();
        SmallVector x_hat(n);
        for (Eigen::Index i = 0; i < n; ++i)
            x_hat[i] = xopt_[i] < 0.0 ? -(2.0 * x[i]) : 2.0 * x[i];
        const SmallVector shifted = x_hat.array() - mu0;
        const SmallVector z = q_ * (scaled_r_ * shifted);
        double sum1 = 0.0;
        double sum2 = 0.0;
        double sum3 = 0.0;
        for (Eigen::Index i = 0; i < n; ++i) {
            sum1 += (x_hat[i] - mu0) * (x_hat[i] - mu0);
            sum2 += (x_hat[i] - mu1_) * (x_hat[i] - mu1_);
            sum3 += std::cos(2.0 * std::numbers::pi * z[i]);
        }
        const double d = static_cast<double>(n);
        return std::min(sum1, d + s_ * sum2) + 10.0 * (d - sum3) + 1e4 * f_pen(x) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    static constexpr double mu0 = 2.5;
    Eigen::VectorXd xopt_;
    Eigen::MatrixXd q_;
    Eigen::MatrixXd scaled_r_; // Lambda^100 R, row i scaled
    double s_ = 0.0;
    double mu1_ = 0.0;
    double fopt_;
};

} // namespace

std::unique_ptr<Function> make_weakly_structured(const InstanceSetup& s) {
    switch (s.function) {
    case 20:
        return std::make_unique<Schwefel>(s);
    case 21:
        return std::make_unique<Gallagher>(s, 101);
    case 22:
        return std::make_unique<Gallagher>(s, 21);
    case 23:
        return std::make_unique<Katsuura>(s);
    case 24:
        return std::make_unique<LunacekBiRastrigin>(s);
    default:
        throw std::logic_error("make_weakly_structured: f" + std::to_string(s.function) +
                               " is not in f20-f24");
    }
}

} // namespace mhb::bbob
