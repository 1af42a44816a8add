// The three kinds of CEC function (simple, hybrid, composition) built from the official data, and
// the recipes that say which basic functions each suite's function numbers are made of
// (cec2017.cpp, cec2022.cpp). A built Function holds everything an evaluation needs (shifts,
// rotation matrices, permutations, the basic functions' constants), is immutable, and is shared
// by every problem of the same suite, function and dimension (shared_function).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "problems/cec/cec_basic.hpp"
#include "problems/cec/cec_data.hpp"

namespace mhb::cec {

// A hybrid's basic functions and the share of the coordinates each takes, in order.
struct HybridRecipe {
    std::vector<Basic> parts;
    std::vector<double> shares; // p_k; group k has ceil(p_k D) coordinates, the last what is left
};

// One component of a composition function: a basic function (rotated or not) or a hybrid built
// from this component's o_k, M_k and shuffle block k. Its value g is taken as
// lambda_numerator * g / lambda_denominator + bias, written as the code writes it (e.g. 10000*g/1e+10).
struct ComponentRecipe {
    Basic basic = Basic::rastrigin;
    bool rotated = true;
    HybridRecipe hybrid; // used when it has parts
    double lambda_numerator = 1.0;
    double lambda_denominator = 1.0;
    double sigma = 10.0;
    double bias = 0.0;
};

struct FunctionRecipe {
    enum class Kind { simple, hybrid, composition };
    Kind kind = Kind::simple;
    std::string name;               // "Shifted and Rotated Zakharov", "Hybrid Function 1 (N = 3)", ...
    double bias = 0.0;              // F* = F(o) + error, the suite's bias
    std::vector<int> dimensions;    // those the official data exist for
    Basic basic = Basic::rastrigin; // simple
    bool rotated = true;            // simple
    HybridRecipe hybrid;            // hybrid
    std::vector<ComponentRecipe> components; // composition
    std::string note;                        // a sentence for the help, or empty
};

// Every function of a suite, index = function number - 1 (cec2017.cpp, cec2022.cpp).
const std::vector<FunctionRecipe>& cec2017_recipes();
const std::vector<FunctionRecipe>& cec2022_recipes();
const std::vector<FunctionRecipe>& recipes(Suite suite);

// The dimensions as text, "10, 30, 50, 100".
std::string dimension_list(const std::vector<int>& dimensions);

class Function {
public:
    virtual ~Function() = default;
    // F(x) including the bias; x holds dimension() numbers. Const, thread-safe, allocates nothing.
    [[nodiscard]] virtual double value(const double* x) const = 0;
    [[nodiscard]] int dimension() const { return static_cast<int>(shift_.size()); }
    // The shift vector o (composition functions: o_1, the optimum's component).
    [[nodiscard]] const Eigen::VectorXd& shift() const { return shift_; }
    // Where the minimum F* = bias is attained: o, except for CEC 2017 F9, whose Levy function has
    // its minimum at z = 1, i.e. at o + M^-1 1 (README Q6).
    [[nodiscard]] const Eigen::VectorXd& minimiser() const { return minimiser_; }

protected:
    explicit Function(Eigen::VectorXd shift) : shift_(shift), minimiser_(std::move(shift)) {}
    void set_minimiser(Eigen::VectorXd x) { minimiser_ = std::move(x); }

private:
    Eigen::VectorXd shift_;
    Eigen::VectorXd minimiser_;
};

// Builds function `number` of `suite` in `dimension` from the official data. Throws
// std::invalid_argument when the number or dimension has no data (the message names what exists).
std::shared_ptr<const Function> build_function(Suite suite, int number, int dimension);

// build_function, built once per process and shared: every problem of the same (suite, number,
// dimension) holds the same object.
std::shared_ptr<const Function> shared_function(Suite suite, int number, int dimension);

// Throws std::invalid_argument unless the official data define function `number` in `dimension`:
// "cec2017: parameter 'dim' = 20 has no official data for f=11 (dim = 10, 30, 50, 100 only)".
void check_available(Suite suite, int number, int dimension);

} // namespace mhb::cec
