// Short constructors for the recipe tables of cec2017.cpp and cec2022.cpp.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "problems/cec/cec_function.hpp"

namespace mhb::cec::recipe {

inline FunctionRecipe simple(std::string name, Basic basic, double bias, std::vector<int> dimensions,
                             bool rotated = true, std::string note = {}) {
    FunctionRecipe r;
    r.kind = FunctionRecipe::Kind::simple;
    r.name = std::move(name);
    r.basic = basic;
    r.bias = bias;
    r.dimensions = std::move(dimensions);
    r.rotated = rotated;
    r.note = std::move(note);
    return r;
}

inline FunctionRecipe hybrid(std::string name, HybridRecipe parts, double bias, std::vector<int> dimensions,
                             std::string note = {}) {
    FunctionRecipe r;
    r.kind = FunctionRecipe::Kind::hybrid;
    r.name = std::move(name);
    r.hybrid = std::move(parts);
    r.bias = bias;
    r.dimensions = std::move(dimensions);
    r.note = std::move(note);
    return r;
}

inline FunctionRecipe composition(std::string name, std::vector<ComponentRecipe> components, double bias,
                                  std::vector<int> dimensions, std::string note = {}) {
    FunctionRecipe r;
    r.kind = FunctionRecipe::Kind::composition;
    r.name = std::move(name);
    r.components = std::move(components);
    r.bias = bias;
    r.dimensions = std::move(dimensions);
    r.note = std::move(note);
    return r;
}

// A composition component: lambda written as the code's quotient, numerator * g / denominator.
inline ComponentRecipe part(Basic basic, double numerator, double denominator, double sigma, double bias,
                            bool rotated = true) {
    ComponentRecipe c;
    c.basic = basic;
    c.rotated = rotated;
    c.lambda_numerator = numerator;
    c.lambda_denominator = denominator;
    c.sigma = sigma;
    c.bias = bias;
    return c;
}

// A composition component that is a hybrid (lambda 1).
inline ComponentRecipe hybrid_part(HybridRecipe parts, double sigma, double bias) {
    ComponentRecipe c;
    c.hybrid = std::move(parts);
    c.sigma = sigma;
    c.bias = bias;
    return c;
}

} // namespace mhb::cec::recipe
