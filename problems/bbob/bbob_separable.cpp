// BBOB separable functions f1-f5: sphere, ellipsoid, Rastrigin, Bueche-Rastrigin, linear slope.
// Definitions: Hansen et al. (2009), checked against COCO's f_sphere.c, f_ellipsoid.c,
// f_rastrigin.c, f_bueche_rastrigin.c and f_linear_slope.c.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "problems/bbob/bbob_function.hpp"
#include "problems/bbob/bbob_random.hpp"
#include "problems/bbob/bbob_transforms.hpp"

namespace mhb::bbob {
namespace {

double rastrigin_core(const SmallVector& z) {
    double cosines = 0.0;
    double squares = 0.0;
    for (Eigen::Index i = 0; i < z.size(); ++i) {
        cosines += std::cos(2.0 * std::numbers::pi * z[i]);
        squares += z[i] * z[i];
    }
    return 10.0 * (static_cast<double>(z.size()) - cosines) + squares;
}

// f1: ||x - x_opt||^2.
class Sphere final : public Function {
public:
    explicit Sphere(const InstanceSetup& s) : xopt_(legacy_xopt(s.rseed, s.dimension)), fopt_(s.f_opt) {}
    double value(const Eigen::VectorXd& x) const override { return (x - xopt_).squaredNorm() + fopt_; }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    double fopt_;
};

// f2: sum 10^(6 (i-1)/(D-1)) z_i^2, z = T_osz(x - x_opt).
class SeparableEllipsoid final : public Function {
public:
    explicit SeparableEllipsoid(const InstanceSetup& s)
        : xopt_(legacy_xopt(s.rseed, s.dimension)), weights_(s.dimension), fopt_(s.f_opt) {
        for (Eigen::Index i = 0; i < s.dimension; ++i)
            weights_[i] = std::pow(1.0e6, static_cast<double>(i) / (static_cast<double>(s.dimension) - 1.0));
    }
    double value(const Eigen::VectorXd& x) const override {
        SmallVector z = x - xopt_;
        t_osz(z);
        return weights_.dot(z.cwiseAbs2()) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    Eigen::VectorXd weights_;
    double fopt_;
};

// f3: Rastrigin of z = Lambda^10 T_asy^0.2(T_osz(x - x_opt)).
class Rastrigin final : public Function {
public:
    explicit Rastrigin(const InstanceSetup& s)
        : xopt_(legacy_xopt(s.rseed, s.dimension)), scales_(lambda_diagonal(10.0, s.dimension)),
          fopt_(s.f_opt) {}
    double value(const Eigen::VectorXd& x) const override {
        SmallVector z = x - xopt_;
        t_osz(z);
        t_asy(z, 0.2);
        z.array() *= scales_.array();
        return rastrigin_core(z) + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    Eigen::VectorXd scales_;
    double fopt_;
};

// f4: Rastrigin of z = s T_osz(x - x_opt), s_i = 10^(0.5 (i-1)/(D-1)), times 10 more for positive
// z_i at odd i (1-based); + 100 f_pen(x). x_opt has its odd (1-based) coordinates made positive, a
// step of the legacy code that the function document leaves out.
class BuecheRastrigin final : public Function {
public:
    explicit BuecheRastrigin(const InstanceSetup& s)
        : xopt_(legacy_xopt(s.rseed, s.dimension)), scales_(s.dimension), fopt_(s.f_opt) {
        for (Eigen::Index i = 0; i < s.dimension; i += 2)
            xopt_[i] = std::fabs(xopt_[i]);
        for (Eigen::Index i = 0; i < s.dimension; ++i)
            scales_[i] =
                std::pow(std::sqrt(10.0), static_cast<double>(i) / (static_cast<double>(s.dimension) - 1.0));
    }
    double value(const Eigen::VectorXd& x) const override {
        SmallVector z = x - xopt_;
        t_osz(z);
        for (Eigen::Index i = 0; i < z.size(); ++i) {
            double factor = scales_[i];
            if (z[i] > 0.0 && i % 2 == 0)
                factor *= 10.0;
            z[i] *= factor;
        }
        return rastrigin_core(z) + fopt_ + 100.0 * f_pen(x);
    }
    Eigen::VectorXd x_opt() const override { return xopt_; }

private:
    Eigen::VectorXd xopt_;
    Eigen::VectorXd scales_;
    double fopt_;
};

// f5: sum 5 |s_i| - s_i z_i, s_i = sign(x_opt_i) 10^((i-1)/(D-1)), z_i = x_i inside the corner's
// half-space (x_i x*_i < 5^2) and x*_i beyond it, so nothing beats the optimum, the corner
// x* = 5 sign(x_opt) of the box.
class LinearSlope final : public Function {
public:
    explicit LinearSlope(const InstanceSetup& s)
        : slopes_(s.dimension), corner_(s.dimension), fopt_(s.f_opt) {
        const Eigen::VectorXd xopt = legacy_xopt(s.rseed, s.dimension);
        for (Eigen::Index i = 0; i < s.dimension; ++i) {
            const double magnitude =
                std::pow(std::sqrt(100.0), static_cast<double>(i) / (static_cast<double>(s.dimension) - 1.0));
            slopes_[i] = xopt[i] > 0.0 ? magnitude : -magnitude;
            corner_[i] = xopt[i] < 0.0 ? -5.0 : 5.0;
        }
    }
    double value(const Eigen::VectorXd& x) const override {
        double result = 0.0;
        for (Eigen::Index i = 0; i < x.size(); ++i) {
            const double z = x[i] * corner_[i] < 25.0 ? x[i] : corner_[i];
            result += 5.0 * std::fabs(slopes_[i]) - slopes_[i] * z;
        }
        return result + fopt_;
    }
    Eigen::VectorXd x_opt() const override { return corner_; }

private:
    Eigen::VectorXd slopes_;
    Eigen::VectorXd corner_;
    double fopt_;
};

} // namespace

std::unique_ptr<Function> make_separable(const InstanceSetup& s) {
    switch (s.function) {
    case 1:
        return std::make_unique<Sphere>(s);
    case 2:
        return std::make_unique<SeparableEllipsoid>(s);
    case 3:
        return std::make_unique<Rastrigin>(s);
    case 4:
        return std::make_unique<BuecheRastrigin>(s);
    case 5:
        return std::make_unique<LinearSlope>(s);
    default:
        throw std::logic_error("make_separable: f" + std::to_string(s.function) + " is not separable");
    }
}

} // namespace mhb::bbob
