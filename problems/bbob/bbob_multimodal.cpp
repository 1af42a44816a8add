// BBOB multi-modal functions with adequate global structure f15-f19: Rastrigin (rotated),
// Weierstrass, Schaffers F7 (condition 10 and 1000), composite Griewank-Rosenbrock F8F2.
// Definitions: Hansen et al. (2009), checked against COCO's f_rastrigin.c, f_weierstrass.c,
// f_schaffers.c and f_griewank_rosenbrock.c.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "problems/bbob/bbob_function.hpp"
#include "problems/bbob/bbob_random.hpp"
#include "problems/bbob/bbob_transforms.hpp"

namespace mhb::bbob {
namespace {

// f15: Rastrigin of z = R Lambda^10 Q T_asy^0.2(T_osz(R (x - x_opt))).
class RastriginRotated final : public Function {
public:
    explicit RastriginRotated(const InstanceSetup& s)
        : xopt_(legacy_xopt(s.rseed, s.dimension)), r_(legacy_rotation(s.rseed + 1000000, s.dimension)),
          m_(rotate_scale_rotate(r_, sqrt_power_diagonal(10.0, s.dimension),
                                 legacy_rotation(s.rseed, s.dimension))),
          fopt_(s.f_opt) {}
    double value(const Eigen::VectorXd& x) const override {
        SmallVector y = r_ * (x - xopt_);
        t_osz(y);
        t_asy(y, 0.2);
        const SmallVector z = m_ * y;
        double cosines = 0.0;
        for (Eigen::Index i = 0; i < z.size(); ++i)
            cosines += std::cos(2.0 * std::numbers::pi * z[i]);
        return 10.0 * (static_cast<double>(z.size()) - cosines) + z.squaredNorm() + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    Eigen::MatrixXd r_;
    Eigen::MatrixXd m_;
    double fopt_;
};

// f16: 10 (1/D sum_i sum_{k=0}^{11} 2^-k cos(2 pi 3^k (z_i + 1/2)) - f0)^3 + 10/D f_pen(x),
// z = R Lambda^(1/100) Q T_osz(R (x - x_opt)).
class Weierstrass final : public Function {
public:
    explicit Weierstrass(const InstanceSetup& s)
        : xopt_(legacy_xopt(s.rseed, s.dimension)), r_(legacy_rotation(s.rseed + 1000000, s.dimension)),
          m_(rotate_scale_rotate(r_, sqrt_power_diagonal(1.0 / 100.0, s.dimension),
                                 legacy_rotation(s.rseed, s.dimension))),
          fopt_(s.f_opt) {
        for (std::size_t k = 0; k < terms; ++k) {
            a_[k] = std::pow(0.5, static_cast<double>(k));
            b_[k] = std::pow(3.0, static_cast<double>(k));
            f0_ += a_[k] * std::cos(2.0 * std::numbers::pi * b_[k] * 0.5);
        }
    }
    double value(const Eigen::VectorXd& x) const override {
        SmallVector y = r_ * (x - xopt_);
        t_osz(y);
        const SmallVector z = m_ * y;
        double sum = 0.0;
        for (Eigen::Index i = 0; i < z.size(); ++i)
            for (std::size_t k = 0; k < terms; ++k)
                sum += std::cos(2.0 * std::numbers::pi * (z[i] + 0.5) * b_[k]) * a_[k];
        const double d = static_cast<double>(z.size());
        return 10.0 * std::pow(sum / d - f0_, 3.0) + fopt_ + 10.0 / d * f_pen(x);
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    static constexpr std::size_t terms = 12;
    Eigen::VectorXd xopt_;
    Eigen::MatrixXd r_;
    Eigen::MatrixXd m_;
    std::array<double, terms> a_{};
    std::array<double, terms> b_{};
    double f0_ = 0.0;
    double fopt_;
};

// f17 (condition 10) and f18 (condition 1000): Schaffers F7 of z = Lambda^c Q T_asy^0.5(R (x - x_opt)),
// + 10 f_pen(x).
class Schaffers final : public Function {
public:
    Schaffers(const InstanceSetup& s, double condition)
        : xopt_(legacy_xopt(s.rseed, s.dimension)), r_(legacy_rotation(s.rseed + 1000000, s.dimension)),
          m_(legacy_rotation(s.rseed, s.dimension)), fopt_(s.f_opt) {
        const Eigen::VectorXd scales = sqrt_power_diagonal(condition, s.dimension);
        for (Eigen::Index i = 0; i < s.dimension; ++i)
            m_.row(i) *= scales[i];
    }
    double value(const Eigen::VectorXd& x) const override {
        SmallVector y = r_ * (x - xopt_);
        t_asy(y, 0.5);
        const SmallVector z = m_ * y;
        double sum = 0.0;
        for (Eigen::Index i = 0; i + 1 < z.size(); ++i) {
            const double s2 = z[i] * z[i] + z[i + 1] * z[i + 1];
            const double wave = std::sin(50.0 * std::pow(s2, 0.1));
            sum += std::pow(s2, 0.25) * (1.0 + wave * wave);
        }
        const double mean = sum / (static_cast<double>(z.size()) - 1.0);
        return mean * mean + fopt_ + 10.0 * f_pen(x);
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    Eigen::MatrixXd r_;
    Eigen::MatrixXd m_; // Lambda^c Q
    double fopt_;
};

// f19: 10/(D-1) sum (s_i / 4000 - cos s_i) + 10, s_i = 100 (z_i^2 - z_{i+1})^2 + (z_i - 1)^2,
// z = max(1, sqrt(D)/8) R x + 1/2; the optimum is R^T 1 / (2 max(1, sqrt(D)/8)).
class GriewankRosenbrock final : public Function {
public:
    explicit GriewankRosenbrock(const InstanceSetup& s)
        : frame_(scaled_rotation_frame(s.rseed, s.dimension)), fopt_(s.f_opt) {}
    double value(const Eigen::VectorXd& x) const override {
        SmallVector z = frame_.m * x;
        z.array() += 0.5;
        double sum = 0.0;
        for (Eigen::Index i = 0; i + 1 < z.size(); ++i) {
            const double c1 = z[i] * z[i] - z[i + 1];
            const double c2 = 1.0 - z[i];
            const double t = 100.0 * c1 * c1 + c2 * c2;
            sum += t / 4000.0 - std::cos(t);
        }
        return 10.0 + 10.0 * sum / static_cast<double>(z.size() - 1) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return frame_.x_opt; }

private:
    ScaledRotationFrame frame_;
    double fopt_;
};

} // namespace

std::unique_ptr<Function> make_multimodal(const InstanceSetup& s) {
    switch (s.function) {
    case 15:
        return std::make_unique<RastriginRotated>(s);
    case 16:
        return std::make_unique<Weierstrass>(s);
    case 17:
        return std::make_unique<Schaffers>(s, 10.0);
    case 18:
        return std::make_unique<Schaffers>(s, 1000.0);
    case 19:
        return std::make_unique<GriewankRosenbrock>(s);
    default:
        throw std::logic_error("make_multimodal: f" + std::to_string(s.function) + " is not in f15-f19");
    }
}

} // namespace mhb::bbob
