// BBOB functions with low or moderate conditioning f6-f9: attractive sector, step ellipsoid,
// Rosenbrock (original and rotated). Definitions: Hansen et al. (2009), checked against COCO's
// f_attractive_sector.c, f_step_ellipsoid.c and f_rosenbrock.c.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "problems/bbob/bbob_function.hpp"
#include "problems/bbob/bbob_random.hpp"
#include "problems/bbob/bbob_transforms.hpp"

namespace mhb::bbob {
namespace {

double rosenbrock_core(const SmallVector& z) {
    double s1 = 0.0;
    double s2 = 0.0;
    for (Eigen::Index i = 0; i + 1 < z.size(); ++i) {
        const double a = z[i] * z[i] - z[i + 1];
        const double b = z[i] - 1.0;
        s1 += a * a;
        s2 += b * b;
    }
    return 100.0 * s1 + s2;
}

// f6: T_osz(sum (s_i z_i)^2)^0.9, z = Q Lambda^10 R (x - x_opt), s_i = 100 where z_i has the sign
// of x_opt_i, else 1.
class AttractiveSector final : public Function {
public:
    explicit AttractiveSector(const InstanceSetup& s)
        : xopt_(legacy_xopt(s.rseed, s.dimension)),
          m_(rotate_scale_rotate(legacy_rotation(s.rseed + 1000000, s.dimension),
                                 sqrt_power_diagonal(10.0, s.dimension),
                                 legacy_rotation(s.rseed, s.dimension))),
          fopt_(s.f_opt) {}
    double value(const Eigen::VectorXd& x) const override {
        const SmallVector z = m_ * (x - xopt_);
        double sum = 0.0;
        for (Eigen::Index i = 0; i < z.size(); ++i)
            sum += (xopt_[i] * z[i] > 0.0 ? 100.0 * 100.0 : 1.0) * z[i] * z[i];
        return std::pow(t_osz(sum), 0.9) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    Eigen::MatrixXd m_;
    double fopt_;
};

// f7: 0.1 max(|z_hat_1| / 1e4, sum 10^(2 (i-1)/(D-1)) z_i^2) + f_pen(x), z_hat = Lambda^10 R (x - x_opt),
// z = Q round(z_hat) (rounded to integers beyond 0.5, to tenths within).
class StepEllipsoid final : public Function {
public:
    explicit StepEllipsoid(const InstanceSetup& s)
        : xopt_(legacy_xopt(s.rseed, s.dimension)), q_(legacy_rotation(s.rseed + 1000000, s.dimension)),
          scaled_r_(legacy_rotation(s.rseed, s.dimension)), weights_(s.dimension), fopt_(s.f_opt) {
        const double d1 = static_cast<double>(s.dimension - 1);
        for (Eigen::Index i = 0; i < s.dimension; ++i) {
            const double c = std::sqrt(std::pow(100.0 / 10.0, static_cast<double>(i) / d1));
            scaled_r_.row(i) *= c;
            weights_[i] = std::pow(100.0, static_cast<double>(i) / d1);
        }
    }
    double value(const Eigen::VectorXd& x) const override {
        SmallVector z_hat = scaled_r_ * (x - xopt_);
        const double first = z_hat[0];
        for (Eigen::Index i = 0; i < z_hat.size(); ++i)
            z_hat[i] =
                std::fabs(z_hat[i]) > 0.5 ? round_half_up(z_hat[i]) : round_half_up(10.0 * z_hat[i]) / 10.0;
        const SmallVector z = q_ * z_hat;
        const double core = weights_.dot(z.cwiseAbs2());
        return 0.1 * std::max(std::fabs(first) * 1.0e-4, core) + f_pen(x) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    Eigen::MatrixXd q_;
    Eigen::MatrixXd scaled_r_; // Lambda^10 R, row i scaled
    Eigen::VectorXd weights_;
    double fopt_;
};

// f8: Rosenbrock of z = max(1, sqrt(D)/8) (x - x_opt) + 1, with x_opt scaled by 0.75.
class Rosenbrock final : public Function {
public:
    explicit Rosenbrock(const InstanceSetup& s)
        : xopt_(0.75 * legacy_xopt(s.rseed, s.dimension)),
          factor_(std::max(1.0, std::sqrt(static_cast<double>(s.dimension)) / 8.0)), fopt_(s.f_opt) {}
    double value(const Eigen::VectorXd& x) const override {
        SmallVector z = factor_ * (x - xopt_);
        z.array() += 1.0;
        return rosenbrock_core(z) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    double factor_;
    double fopt_;
};

// f9: Rosenbrock of z = max(1, sqrt(D)/8) R x + 1/2; the optimum is R^T 1 / (2 max(1, sqrt(D)/8)).
class RosenbrockRotated final : public Function {
public:
    explicit RosenbrockRotated(const InstanceSetup& s)
        : frame_(scaled_rotation_frame(s.rseed, s.dimension)), fopt_(s.f_opt) {}
    double value(const Eigen::VectorXd& x) const override {
        SmallVector z = frame_.m * x;
        z.array() += 0.5;
        return rosenbrock_core(z) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return frame_.x_opt; }

private:
    ScaledRotationFrame frame_;
    double fopt_;
};

} // namespace

std::unique_ptr<Function> make_moderate(const InstanceSetup& s) {
    switch (s.function) {
    case 6:
        return std::make_unique<AttractiveSector>(s);
    case 7:
        return std::make_unique<StepEllipsoid>(s);
    case 8:
        return std::make_unique<Rosenbrock>(s);
    case 9:
        return std::make_unique<RosenbrockRotated>(s);
    default:
        throw std::logic_error("make_moderate: f" + std::to_string(s.function) + " is not in f6-f9");
    }
}

} // namespace mhb::bbob
