// The classic problem families: one registry entry per classic function (sphere, rastrigin, ...),
// each with dim, bound, shift, rotate and instance (and noise for the quartic function), e.g.
// `rastrigin:dim=30,shift=1,rotate=1,instance=3`. How an instance shifts and rotates is in
// instance_transform.hpp; everything it draws is computed here once, at construction.
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/core/matrix_vector.hpp"
#include "problems/core/parameters.hpp"
#include "problems/functions/classic_function.hpp"
#include "problems/functions/instance_transform.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

// Rotations are D x D and cost D^2 per evaluation; beyond this they are refused.
constexpr Eigen::Index max_rotated_dimension = 2000;

struct ClassicOptions {
    Eigen::Index dimension = 10;
    double lower = 0.0;
    double upper = 0.0;
    bool shift = false;
    bool rotate = false;
    std::int64_t instance = 1;
    double noise = 0.0;
};

class ClassicProblem final : public Problem {
public:
    ClassicProblem(const ClassicFunction& function, const ClassicOptions& o)
        : function_(function),
          value_(function.bind(o.dimension)), box_{Eigen::VectorXd::Constant(o.dimension, o.lower),
                                                   Eigen::VectorXd::Constant(o.dimension, o.upper)},
          own_optimum_(Eigen::VectorXd::Constant(o.dimension, function.optimum)), optimum_(own_optimum_),
          shifted_(o.shift), rotated_(o.rotate), noise_(o.noise),
          noise_seed_(instance_seed(function.name, "noise", o.instance)) {
        box_.validate(function.name);
        if (!box_.contains(own_optimum_))
            throw std::invalid_argument(function.name + ": the box [" + format_real(o.lower) + ", " +
                                        format_real(o.upper) + "]^dim excludes the optimum at " +
                                        format_real(function.optimum) +
                                        " in every coordinate; widen 'bound'");
        if (shifted_)
            optimum_ = draw_shift(function.name, o.instance, box_);
        if (rotated_)
            rotation_ = draw_rotation(function.name, o.instance, o.dimension);
        f_star_ = value_(
            std::span<const double>(own_optimum_.data(), static_cast<std::size_t>(own_optimum_.size())));
    }

    std::string name() const override { return function_.name; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    std::optional<KnownOptimum> known_optimum() const override { return KnownOptimum{f_star_, optimum_}; }

    double evaluate(const Eigen::VectorXd& x) const override {
        double f = 0.0;
        if (!shifted_ && !rotated_) {
            f = value_(std::span<const double>(x.data(), static_cast<std::size_t>(x.size())));
        } else if (x.size() <= small) {
            // Small dimensions (the usual case) use stack buffers: no allocation per evaluation.
            std::array<double, small> d_buffer;
            std::array<double, small> z_buffer;
            f = transformed_value(x, d_buffer.data(), z_buffer.data());
        } else {
            std::vector<double> d_buffer(static_cast<std::size_t>(x.size()));
            std::vector<double> z_buffer(static_cast<std::size_t>(x.size()));
            f = transformed_value(x, d_buffer.data(), z_buffer.data());
        }
        if (noise_ > 0.0)
            f += noise_ * hash_uniform(noise_seed_, x);
        return f;
    }

private:
    static constexpr Eigen::Index small = 64;

    // z = Q (x - c) + x*; at x = c this is exactly x*, so f(c) = f* to the bit.
    double transformed_value(const Eigen::VectorXd& x, double* d_data, double* z_data) const {
        const Eigen::Index n = x.size();
        Eigen::Map<Eigen::VectorXd> d(d_data, n);
        Eigen::Map<Eigen::VectorXd> z(z_data, n);
        d = x - optimum_;
        if (rotated_)
            multiply_square(rotation_, d_data, z_data); // Eigen's product, bit for bit
        else
            z = d;
        z += own_optimum_;
        return value_(std::span<const double>(z_data, static_cast<std::size_t>(n)));
    }

    const ClassicFunction& function_;
    ClassicEvaluator value_;
    Box box_;
    Eigen::VectorXd own_optimum_; // x* in the function's own coordinates
    Eigen::VectorXd optimum_;     // c: where the optimum is in this variant
    Eigen::MatrixXd rotation_;
    bool shifted_;
    bool rotated_;
    double noise_;
    std::uint64_t noise_seed_;
    double f_star_ = 0.0;
};

std::vector<ParameterInfo> classic_parameters(const ClassicFunction& f) {
    const bool symmetric = f.lower == -f.upper;
    // Built by appending: GCC 12's -Wrestrict misfires on `"[" + std::string`.
    std::string usual = "[";
    usual.append(format_real(f.lower)).append(", ").append(format_real(f.upper)).append("]");
    ParameterInfo bound =
        ParameterInfo::real("bound", f.upper, 0.0, 1e12,
                            "half-width of the box [-bound, bound]^dim; default: the usual box " + usual +
                                "^dim")
            .open_below();
    if (!symmetric)
        bound.default_value.clear(); // no default: without it the usual (asymmetric) box is used
    std::vector<ParameterInfo> list = {
        ParameterInfo::integer("dim", 10, static_cast<long long>(f.min_dimension), 10000, "dimension"),
        std::move(bound),
        ParameterInfo::boolean(
            "shift", false,
            "move the optimum to a point drawn from the instance, uniform in the central 80% of "
            "the box"),
        ParameterInfo::boolean("rotate", false,
                               "turn the coordinates about the optimum by a rotation drawn from the instance "
                               "(dim <= 2000)"),
        ParameterInfo::integer(
            "instance", 1, 1, 100000,
            "which shift, rotation (and noise) to draw; the same number gives the same instance "
            "everywhere; a range such as 1-5 expands")
            .ranged()};
    if (f.noisy)
        list.push_back(
            ParameterInfo::real("noise", 1.0, 0.0, 1e12,
                                "amplitude of the noise added to f, noise U[0, 1), a deterministic hash "
                                "of (instance, x)"));
    return list;
}

} // namespace

const std::vector<ClassicFunction>& classic_functions() {
    static const std::vector<ClassicFunction> all = [] {
        std::vector<ClassicFunction> list = classic_unimodal_functions();
        for (auto& f : classic_multimodal_functions())
            list.push_back(std::move(f));
        return list;
    }();
    return all;
}

std::vector<std::string> classic_function_names() {
    std::vector<std::string> names;
    for (const auto& f : classic_functions())
        names.push_back(f.name);
    return names;
}

std::vector<std::string> centre_bias_problem_specs(Eigen::Index dimension, std::int64_t instance) {
    std::vector<std::string> specs;
    for (const auto& name : classic_function_names()) {
        const std::string plain = name + ":dim=" + std::to_string(dimension);
        specs.push_back(plain);
        specs.push_back(plain + ",instance=" + std::to_string(instance) + ",shift=on");
    }
    return specs;
}

void register_classic_functions(ProblemRegistry& registry) {
    for (const ClassicFunction& f : classic_functions()) {
        registry.add({f.name, f.version, f.summary, f.reference, classic_parameters(f),
                      [&f](const ParameterValues& p) -> std::unique_ptr<Problem> {
                          ClassicOptions o;
                          o.dimension = static_cast<Eigen::Index>(p.integer("dim"));
                          o.lower = f.lower;
                          o.upper = f.upper;
                          if (p.has("bound")) {
                              o.lower = -p.real("bound");
                              o.upper = p.real("bound");
                          }
                          o.shift = p.boolean("shift");
                          o.rotate = p.boolean("rotate");
                          o.instance = static_cast<std::int64_t>(p.integer("instance"));
                          o.noise = f.noisy ? p.real("noise") : 0.0;
                          if (o.rotate && o.dimension > max_rotated_dimension)
                              throw std::invalid_argument(f.name + ": parameter 'rotate' needs dim <= " +
                                                          std::to_string(max_rotated_dimension) +
                                                          " (dim = " + std::to_string(o.dimension) + ")");
                          return std::make_unique<ClassicProblem>(f, o);
                      }});
    }
}

} // namespace mhb
