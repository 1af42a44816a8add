// Simple, hybrid and composition functions (../shared/cec/README.md, section 4), built once from
// the official data and evaluated without allocating: every per-call vector is a stack buffer of
// max_dimension doubles, rotations are matrix-vector products (problems/core/matrix_vector.hpp).
#include "problems/cec/cec_function.hpp"

#include <Eigen/LU>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>
#include <variant>

#include "problems/core/matrix_vector.hpp"

namespace mhb::cec {
namespace {

using Buffer = std::array<double, max_dimension>;
// Column-major: Eigen's column-major matrix-vector product is the faster one at every D of the data.
using Rotation = Eigen::MatrixXd;

// out = M in, out_i = sum_j M[i][j] in_j with M as stored in the file (read row by row, not transposed).
void rotate(const Rotation& m, const double* in, double* out, int n) {
    if (n <= 4) { // below Eigen's call overhead
        for (int i = 0; i < n; ++i) {
            double sum = 0.0;
            for (int j = 0; j < n; ++j)
                sum += m(i, j) * in[j];
            out[i] = sum;
        }
        return;
    }
    multiply_square(m, in, out); // Eigen's product, bit for bit; AVX2 where the processor has it
}

// A basic function of x - o: scaled, then rotated by M unless `rotation` is empty.
//
// Components take x and o rather than a precomputed x - o: each per-call vector is then written
// once and read by a later loop of the same width, never written in scalars and read back in
// pairs (a store-forwarding stall that cost more than the whole function at D = 2).
class ShiftedBasic {
public:
    ShiftedBasic(Basic basic, int dimension, const double* shift, Rotation rotation)
        : shape_(basic, dimension, shift), rotation_(std::move(rotation)) {}

    double operator()(const double* x, const double* o) const {
        const int n = shape_.size();
        Buffer y;
        Buffer z;
        const double s = shape_.scale();
        for (int i = 0; i < n; ++i)
            y[static_cast<std::size_t>(i)] = (x[i] - o[i]) * s;
        if (rotation_.size() == 0)
            return shape_(y.data());
        if (shape_.basic() == Basic::lunacek_bi_rastrigin) {
            // README Q4: only the cosine term sees the rotation.
            shape_.lunacek_flip(y.data());
            rotate(rotation_, y.data(), z.data(), n);
            return shape_.lunacek_value(y.data(), z.data());
        }
        rotate(rotation_, y.data(), z.data(), n);
        return shape_(z.data());
    }

private:
    BasicShape shape_;
    Rotation rotation_;
};

// A hybrid function of x - o (README section 4, Q1, Q5, Q11): z = M (x - o), y_i = z_{S_i},
// consecutive groups of y through their basic functions, each with its own scale only.
class ShuffledHybrid {
public:
    ShuffledHybrid(const HybridRecipe& recipe, int dimension, const double* shift, Rotation rotation,
                   std::vector<int> permutation)
        : dimension_(dimension), rotation_(std::move(rotation)), permutation_(std::move(permutation)) {
        int used = 0;
        const auto count = recipe.parts.size();
        for (std::size_t k = 0; k < count; ++k) {
            // As the code: ceil(p_k D) for all but the last group, which takes what is left.
            const int n =
                k + 1 < count ? static_cast<int>(std::ceil(recipe.shares[k] * dimension)) : dimension - used;
            if (n < 1 || used + n > dimension)
                throw std::logic_error("cec: a hybrid's groups do not fit its dimension");
            // Lunacek bi-Rastrigin takes its signs from the first n entries of the hybrid's own
            // shift, not from the group's positions (README Q5).
            parts_.emplace_back(recipe.parts[k], n, shift);
            // README Q1: the code's Schaffer F7 reads the first n entries of the whole permuted
            // vector y, whatever group it is given.
            starts_.push_back(recipe.parts[k] == Basic::schaffer_f7 ? 0 : used);
            used += n;
        }
    }

    double operator()(const double* x, const double* o) const {
        Buffer difference;
        Buffer z;
        Buffer group;
        for (int i = 0; i < dimension_; ++i)
            difference[static_cast<std::size_t>(i)] = x[i] - o[i];
        rotate(rotation_, difference.data(), z.data(), dimension_);
        double f = 0.0;
        for (std::size_t k = 0; k < parts_.size(); ++k) {
            const BasicShape& part = parts_[k];
            // Group k is y_start ... y_(start+n-1), y_i = z_(S_i), times the part's own scale.
            const int* index = permutation_.data() + starts_[k];
            const double s = part.scale();
            for (int i = 0; i < part.size(); ++i)
                group[static_cast<std::size_t>(i)] = z[static_cast<std::size_t>(index[i])] * s;
            f += part(group.data());
        }
        return f;
    }

private:
    int dimension_;
    Rotation rotation_;
    std::vector<int> permutation_; // 0-based: y_i = z[permutation_[i]]
    std::vector<BasicShape> parts_;
    std::vector<int> starts_; // where each part's group starts in y
};

using Component = std::variant<ShiftedBasic, ShuffledHybrid>;

// A simple (G = ShiftedBasic) or hybrid (G = ShuffledHybrid) function on its own: g(x - o) + bias.
template <class G> class Standalone final : public Function {
public:
    Standalone(Eigen::VectorXd shift, G g, double bias)
        : Function(std::move(shift)), g_(std::move(g)), bias_(bias) {}

    double value(const double* x) const override { return g_(x, shift().data()) + bias_; }

    using Function::set_minimiser;

private:
    G g_;
    double bias_;
};

// sum_k w_k / sum(w) (lambda_k g_k + bias_k) + F*, with the weights of README Q10.
class Composition final : public Function {
public:
    struct Part {
        Component g;
        Eigen::VectorXd shift;
        double lambda_numerator;
        double lambda_denominator;
        double sigma;
        double bias;
    };
    static constexpr std::size_t max_parts = 8;

    Composition(std::vector<Part> parts, double bias)
        : Function(parts.front().shift), parts_(std::move(parts)), bias_(bias) {}

    double value(const double* x) const override {
        std::array<double, max_parts> fit{};
        std::array<double, max_parts> weight{};
        const int n = dimension();
        double weight_max = 0.0;
        for (std::size_t k = 0; k < parts_.size(); ++k) {
            const Part& part = parts_[k];
            const double* o = part.shift.data();
            const double g = std::visit([x, o](const auto& c) { return c(x, o); }, part.g);
            fit[k] = part.lambda_numerator * g / part.lambda_denominator + part.bias;
            double distance = 0.0;
            for (int j = 0; j < n; ++j)
                distance += (x[j] - o[j]) * (x[j] - o[j]);
            // At o_k exactly the code's weight is its INF, 1e99: finite, so the others still count.
            weight[k] = distance != 0 ? std::sqrt(1.0 / distance) *
                                            std::exp(-distance / 2.0 / n / (part.sigma * part.sigma))
                                      : 1e99;
            if (weight[k] > weight_max)
                weight_max = weight[k];
        }
        double weight_sum = 0.0;
        for (std::size_t k = 0; k < parts_.size(); ++k)
            weight_sum += weight[k];
        if (weight_max == 0) { // every weight underflowed: equal weights
            for (std::size_t k = 0; k < parts_.size(); ++k)
                weight[k] = 1;
            weight_sum = static_cast<double>(parts_.size());
        }
        double f = 0.0;
        for (std::size_t k = 0; k < parts_.size(); ++k)
            f += weight[k] / weight_sum * fit[k];
        return f + bias_;
    }

private:
    std::vector<Part> parts_;
    double bias_;
};

std::string data_name(const char* stem, int number, int dimension) {
    std::string name = std::string(stem) + "_" + std::to_string(number);
    if (dimension > 0)
        name += "_D" + std::to_string(dimension);
    return name + ".txt";
}

Eigen::VectorXd to_vector(const std::vector<double>& numbers) {
    return Eigen::Map<const Eigen::VectorXd>(numbers.data(), static_cast<Eigen::Index>(numbers.size()));
}

// Matrix `block` of a stacked matrix file: tokens block D^2 ... (block + 1) D^2 - 1, row-major.
Rotation matrix_block(const DataFile& file, int block, int dimension) {
    const auto d = static_cast<std::size_t>(dimension);
    const std::vector<double> numbers = file.range(static_cast<std::size_t>(block) * d * d, d * d);
    return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        numbers.data(), dimension, dimension);
}

// Shuffle block `block` (1-based indices in the file) as 0-based indices; it must be a permutation.
std::vector<int> permutation_block(const DataFile& file, int block, int dimension) {
    const auto d = static_cast<std::size_t>(dimension);
    const std::vector<double> numbers = file.range(static_cast<std::size_t>(block) * d, d);
    std::vector<int> out(d);
    std::vector<bool> seen(d, false);
    for (std::size_t i = 0; i < d; ++i) {
        const double v = numbers[i];
        if (!(v >= 1 && v <= dimension && v == std::floor(v)) || seen[static_cast<std::size_t>(v) - 1])
            throw std::runtime_error(file.name + ": shuffle block " + std::to_string(block + 1) +
                                     " is not a permutation of 1..." + std::to_string(dimension));
        seen[static_cast<std::size_t>(v) - 1] = true;
        out[i] = static_cast<int>(v) - 1;
    }
    return out;
}

const FunctionRecipe& recipe_of(Suite suite, int number) {
    const auto& all = recipes(suite);
    if (number < 1 || number > static_cast<int>(all.size()))
        throw std::invalid_argument(std::string(suite_name(suite)) +
                                    ": parameter 'f' = " + std::to_string(number) + " is outside [1, " +
                                    std::to_string(all.size()) + "]");
    return all[static_cast<std::size_t>(number) - 1];
}

// CEC 2017 F9: Levy's minimum is at z = M (x - o) = 1, x = o + M^-1 1, when M is invertible and
// that point is in the search box; otherwise o (where F is 900 + 1.44... at D = 10).
Eigen::VectorXd levy_2017_minimiser(const Eigen::VectorXd& shift, const Rotation& m) {
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(m);
    if (!lu.isInvertible())
        return shift;
    const Eigen::VectorXd x = shift + lu.solve(Eigen::VectorXd::Ones(shift.size()));
    return x.cwiseAbs().maxCoeff() <= 100.0 ? x : shift;
}

} // namespace

const std::vector<FunctionRecipe>& recipes(Suite suite) {
    return suite == Suite::cec2017 ? cec2017_recipes() : cec2022_recipes();
}

std::string dimension_list(const std::vector<int>& dimensions) {
    std::string out;
    for (const int d : dimensions)
        out += (out.empty() ? "" : ", ") + std::to_string(d);
    return out;
}

void check_available(Suite suite, int number, int dimension) {
    const FunctionRecipe& recipe = recipe_of(suite, number);
    for (const int d : recipe.dimensions)
        if (d == dimension)
            return;
    throw std::invalid_argument(std::string(suite_name(suite)) +
                                ": parameter 'dim' = " + std::to_string(dimension) +
                                " has no official data for f=" + std::to_string(number) +
                                " (dim = " + dimension_list(recipe.dimensions) + " only)");
}

std::shared_ptr<const Function> build_function(Suite suite, int number, int dimension) {
    check_available(suite, number, dimension);
    const FunctionRecipe& recipe = recipe_of(suite, number);
    const auto d = static_cast<std::size_t>(dimension);
    const auto shifts = data_file(suite, data_name("shift_data", number, 0));
    const auto matrices = data_file(suite, data_name("M", number, dimension));

    if (recipe.kind == FunctionRecipe::Kind::simple) {
        // The code reads o as the first D numbers of the file, M as its first D^2.
        const Eigen::VectorXd o = to_vector(shifts->range(0, d));
        const Rotation m = matrix_block(*matrices, 0, dimension);
        auto function = std::make_shared<Standalone<ShiftedBasic>>(
            o, ShiftedBasic(recipe.basic, dimension, o.data(), recipe.rotated ? m : Rotation()), recipe.bias);
        if (recipe.basic == Basic::levy_2017)
            function->set_minimiser(levy_2017_minimiser(o, m));
        return function;
    }
    if (recipe.kind == FunctionRecipe::Kind::hybrid) {
        const Eigen::VectorXd o = to_vector(shifts->range(0, d));
        const auto shuffle = data_file(suite, data_name("shuffle_data", number, dimension));
        return std::make_shared<Standalone<ShuffledHybrid>>(
            o,
            ShuffledHybrid(recipe.hybrid, dimension, o.data(), matrix_block(*matrices, 0, dimension),
                           permutation_block(*shuffle, 0, dimension)),
            recipe.bias);
    }

    // Composition: o_k is the first D numbers of line k, M_k the k-th D x D block (README Q9).
    if (recipe.components.size() > Composition::max_parts)
        throw std::logic_error("cec: a composition of more than 8 functions");
    std::shared_ptr<const DataFile> shuffle;
    std::vector<Composition::Part> parts;
    for (std::size_t k = 0; k < recipe.components.size(); ++k) {
        const ComponentRecipe& c = recipe.components[k];
        const int block = static_cast<int>(k);
        Eigen::VectorXd o = to_vector(shifts->line_prefix(k, d));
        Rotation m = matrix_block(*matrices, block, dimension);
        Component g = [&]() -> Component {
            if (!c.hybrid.parts.empty()) {
                if (!shuffle)
                    shuffle = data_file(suite, data_name("shuffle_data", number, dimension));
                return Component(std::in_place_type<ShuffledHybrid>, c.hybrid, dimension, o.data(),
                                 std::move(m), permutation_block(*shuffle, block, dimension));
            }
            return Component(std::in_place_type<ShiftedBasic>, c.basic, dimension, o.data(),
                             c.rotated ? std::move(m) : Rotation());
        }();
        parts.push_back(
            {std::move(g), std::move(o), c.lambda_numerator, c.lambda_denominator, c.sigma, c.bias});
    }
    return std::make_shared<Composition>(std::move(parts), recipe.bias);
}

std::shared_ptr<const Function> shared_function(Suite suite, int number, int dimension) {
    static std::mutex mutex;
    static std::map<std::tuple<Suite, int, int>, std::shared_ptr<const Function>> built;
    check_available(suite, number, dimension);
    const std::lock_guard lock(mutex);
    auto& slot = built[{suite, number, dimension}];
    if (!slot)
        slot = build_function(suite, number, dimension);
    return slot;
}

} // namespace mhb::cec
