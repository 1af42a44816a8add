// BBOB functions with high conditioning f10-f14: ellipsoid, discus, bent cigar, sharp ridge,
// different powers (all rotated). Definitions: Hansen et al. (2009), checked against COCO's
// f_ellipsoid.c, f_discus.c, f_bent_cigar.c, f_sharp_ridge.c and f_different_powers.c.
#include <cmath>
#include <stdexcept>
#include <string>

#include "problems/bbob/bbob_function.hpp"
#include "problems/bbob/bbob_random.hpp"
#include "problems/bbob/bbob_transforms.hpp"

namespace mhb::bbob {
namespace {

// The shape shared by f10-f14: z = M (x - x_opt) for a matrix fixed at construction, then a core.
class RotatedFunction : public Function {
public:
    RotatedFunction(Eigen::VectorXd xopt, Eigen::MatrixXd m, double fopt)
        : xopt_(std::move(xopt)), m_(std::move(m)), fopt_(fopt) {}
    double value(const Eigen::VectorXd& x) const final {
        SmallVector z = m_ * (x - xopt_);
        return core(z) + fopt_;
    }
    Eigen::VectorXd x_opt() const final { return xopt_; }

protected:
    // May change z (it is scratch).
    virtual double core(SmallVector& z) const = 0;

private:
    Eigen::VectorXd xopt_;
    Eigen::MatrixXd m_;
    double fopt_;
};

Eigen::VectorXd power_weights(double base, double exponent_scale, Eigen::Index dimension) {
    Eigen::VectorXd w(dimension);
    for (Eigen::Index i = 0; i < dimension; ++i)
        w[i] =
            std::pow(base, exponent_scale * static_cast<double>(i) / (static_cast<double>(dimension) - 1.0));
    return w;
}

// f10: sum 10^(6 (i-1)/(D-1)) z_i^2, z = T_osz(R (x - x_opt)).
class RotatedEllipsoid final : public RotatedFunction {
public:
    explicit RotatedEllipsoid(const InstanceSetup& s)
        : RotatedFunction(legacy_xopt(s.rseed, s.dimension), legacy_rotation(s.rseed + 1000000, s.dimension),
                          s.f_opt),
          weights_(power_weights(1.0e6, 1.0, s.dimension)) {}

private:
    double core(SmallVector& z) const override {
        t_osz(z);
        return weights_.dot(z.cwiseAbs2());
    }
    Eigen::VectorXd weights_;
};

// f11: 10^6 z_1^2 + sum_{i>1} z_i^2, z = T_osz(R (x - x_opt)).
class Discus final : public RotatedFunction {
public:
    explicit Discus(const InstanceSetup& s)
        : RotatedFunction(legacy_xopt(s.rseed, s.dimension), legacy_rotation(s.rseed + 1000000, s.dimension),
                          s.f_opt) {}

private:
    double core(SmallVector& z) const override {
        t_osz(z);
        return 1.0e6 * z[0] * z[0] + z.tail(z.size() - 1).squaredNorm();
    }
};

// f12: z_1^2 + 10^6 sum_{i>1} z_i^2, z = R T_asy^0.5(R (x - x_opt)). Both x_opt and R are drawn
// from rseed + 10^6 (as in the legacy code).
class BentCigar final : public RotatedFunction {
public:
    explicit BentCigar(const InstanceSetup& s)
        : RotatedFunction(legacy_xopt(s.rseed + 1000000, s.dimension),
                          legacy_rotation(s.rseed + 1000000, s.dimension), s.f_opt),
          r_(legacy_rotation(s.rseed + 1000000, s.dimension)) {}

private:
    double core(SmallVector& z) const override {
        t_asy(z, 0.5);
        const SmallVector y = r_ * z;
        return y[0] * y[0] + 1.0e6 * y.tail(y.size() - 1).squaredNorm();
    }
    Eigen::MatrixXd r_;
};

// f13: z_1^2 + 100 sqrt(sum_{i>1} z_i^2), z = Q Lambda^10 R (x - x_opt).
class SharpRidge final : public RotatedFunction {
public:
    explicit SharpRidge(const InstanceSetup& s)
        : RotatedFunction(legacy_xopt(s.rseed, s.dimension),
                          rotate_scale_rotate(legacy_rotation(s.rseed + 1000000, s.dimension),
                                              sqrt_power_diagonal(10.0, s.dimension),
                                              legacy_rotation(s.rseed, s.dimension)),
                          s.f_opt) {}

private:
    double core(SmallVector& z) const override {
        return 100.0 * std::sqrt(z.tail(z.size() - 1).squaredNorm()) + z[0] * z[0];
    }
};

// f14: sqrt(sum |z_i|^(2 + 4 (i-1)/(D-1))), z = R (x - x_opt).
class DifferentPowers final : public RotatedFunction {
public:
    explicit DifferentPowers(const InstanceSetup& s)
        : RotatedFunction(legacy_xopt(s.rseed, s.dimension), legacy_rotation(s.rseed + 1000000, s.dimension),
                          s.f_opt),
          exponents_(s.dimension) {
        for (Eigen::Index i = 0; i < s.dimension; ++i)
            exponents_[i] = 2.0 + (4.0 * static_cast<double>(i)) / (static_cast<double>(s.dimension) - 1.0);
    }

private:
    double core(SmallVector& z) const override {
        double sum = 0.0;
        for (Eigen::Index i = 0; i < z.size(); ++i)
            sum += std::pow(std::fabs(z[i]), exponents_[i]);
        return std::sqrt(sum);
    }
    Eigen::VectorXd exponents_;
};

} // namespace

std::unique_ptr<Function> make_ill_conditioned(const InstanceSetup& s) {
    switch (s.function) {
    case 10:
        return std::make_unique<RotatedEllipsoid>(s);
    case 11:
        return std::make_unique<Discus>(s);
    case 12:
        return std::make_unique<BentCigar>(s);
    case 13:
        return std::make_unique<SharpRidge>(s);
    case 14:
        return std::make_unique<DifferentPowers>(s);
    default:
        throw std::logic_error("make_ill_conditioned: f" + std::to_string(s.function) + " is not in f10-f14");
    }
}

} // namespace mhb::bbob
