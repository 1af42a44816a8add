// The classic test functions (sphere, Rastrigin, Ackley, ... the set of Yao, Liu and Lin 1999
// and its usual companions), described once each: formula, usual box, where the optimum is,
// the paper. classic_problem.cpp turns a description into a problem family with plain,
// shifted and shifted+rotated variants (see instance_transform.hpp).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace mhb {

// f of the function's own coordinates z, for one dimension (bound once, so that constants such
// as an ellipsoid's weights are computed once, not per evaluation).
using ClassicEvaluator = std::function<double(std::span<const double> z)>;

// The binder of a function that needs no per-dimension constants.
template <double (*F)(std::span<const double>)> ClassicEvaluator stateless(Eigen::Index) {
    return F;
}

struct ClassicFunction {
    std::string name;      // the family name, e.g. "rastrigin"
    std::string summary;   // formula and character, one line
    std::string reference; // where it is defined
    double lower = -100.0; // the usual box, [lower, upper]^D
    double upper = 100.0;
    double optimum = 0.0; // x* = (optimum, ..., optimum) in the function's own coordinates
    Eigen::Index min_dimension = 1;
    bool noisy = false; // adds deterministic uniform noise (the quartic function)
    ClassicEvaluator (*bind)(Eigen::Index dimension) = nullptr;
    int version = 1; // its implementation version (problems/core/registry.hpp)
};

// The unimodal ones (classic_unimodal.cpp) and the multimodal ones (classic_multimodal.cpp).
std::vector<ClassicFunction> classic_unimodal_functions();
std::vector<ClassicFunction> classic_multimodal_functions();

// Every classic function, unimodal first, in a fixed order.
const std::vector<ClassicFunction>& classic_functions();

// Their family names in the same order, e.g. for a study over the whole classic set (the
// centre-bias preset runs each one unshifted and shifted).
std::vector<std::string> classic_function_names();

// The problems of the centre-bias study: each classic function in `dimension` dimensions as it is
// (optimum at the centre or at a fixed point such as (1, ..., 1)) and shifted (optimum drawn from
// `instance`), as specs: "rastrigin:dim=30", "rastrigin:dim=30,instance=1,shift=on", ... Run with the
// same seeds, the gap between the two shows how much an algorithm owes to the optimum's position.
std::vector<std::string> centre_bias_problem_specs(Eigen::Index dimension, std::int64_t instance = 1);

} // namespace mhb
