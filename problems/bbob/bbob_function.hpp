// One BBOB function instance (function 1-24, dimension 2-40, instance >= 1), with everything
// that defines it (x_opt, f_opt, rotations, scalings) computed once at construction, so that an
// evaluation is only the arithmetic of the function (no rotation is ever recomputed).
// The functions are grouped as the BBOB definitions document groups them, one file per group:
// bbob_separable.cpp (f1-f5), bbob_moderate.cpp (f6-f9), bbob_ill_conditioned.cpp (f10-f14),
// bbob_multimodal.cpp (f15-f19), bbob_weakly_structured.cpp (f20-f24).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>

namespace mhb::bbob {

// What every function's construction starts from.
struct InstanceSetup {
    int function = 1;
    Eigen::Index dimension = 2;
    std::int64_t instance = 1;
    std::int64_t rseed = 0; // instance_seed(function, instance)
    double f_opt = 0.0;
};

class Function {
public:
    virtual ~Function() = default;
    // f(x) including f_opt; x has the instance's dimension. Const and thread-safe.
    [[nodiscard]] virtual double value(const Eigen::VectorXd& x) const = 0;
    // Where f_opt is attained.
    [[nodiscard]] virtual Eigen::VectorXd x_opt() const = 0;
};

// Throws std::invalid_argument for a function outside 1-24 or a dimension outside 2-40.
std::unique_ptr<Function> make_function(int function, Eigen::Index dimension, std::int64_t instance);

// One factory per group; each accepts only its own functions.
std::unique_ptr<Function> make_separable(const InstanceSetup& setup);
std::unique_ptr<Function> make_moderate(const InstanceSetup& setup);
std::unique_ptr<Function> make_ill_conditioned(const InstanceSetup& setup);
std::unique_ptr<Function> make_multimodal(const InstanceSetup& setup);
std::unique_ptr<Function> make_weakly_structured(const InstanceSetup& setup);

// The frame of f9 and f19: z = M x + 1/2 with M = max(1, sqrt(D)/8) R (R drawn from rseed), whose
// optimum z = 1 is at x = R^T 1 / (2 max(1, sqrt(D)/8)).
struct ScaledRotationFrame {
    Eigen::MatrixXd m;
    Eigen::VectorXd x_opt;
};
ScaledRotationFrame scaled_rotation_frame(std::int64_t rseed, Eigen::Index dimension);

// R diag(scales) Q, the product that many functions apply after the shift, computed once.
Eigen::MatrixXd rotate_scale_rotate(const Eigen::MatrixXd& r, const Eigen::VectorXd& scales,
                                    const Eigen::MatrixXd& q);

} // namespace mhb::bbob
