// The unimodal classic functions. Formulas and usual boxes as in Yao, Liu and Lin (1999),
// "Evolutionary programming made faster", IEEE TEVC 3(2), table I (f1-f7), unless named otherwise.
#include <algorithm>
#include <cmath>

#include "problems/functions/classic_function.hpp"

namespace mhb {
namespace {

double sphere(std::span<const double> z) {
    double sum = 0.0;
    for (const double v : z)
        sum += v * v;
    return sum;
}

double schwefel_1_2(std::span<const double> z) {
    double sum = 0.0;
    double prefix = 0.0;
    for (const double v : z) {
        prefix += v;
        sum += prefix * prefix;
    }
    return sum;
}

double schwefel_2_21(std::span<const double> z) {
    double largest = 0.0;
    for (const double v : z)
        largest = std::max(largest, std::fabs(v));
    return largest;
}

double schwefel_2_22(std::span<const double> z) {
    double sum = 0.0;
    double product = 1.0;
    bool has_zero = false; // a zero factor makes the product 0 even after it has overflowed to inf
    for (const double v : z) {
        sum += std::fabs(v);
        has_zero = has_zero || v == 0.0;
        product *= std::fabs(v);
    }
    return sum + (has_zero ? 0.0 : product);
}

double step(std::span<const double> z) {
    double sum = 0.0;
    for (const double v : z) {
        const double s = std::floor(v + 0.5);
        sum += s * s;
    }
    return sum;
}

// The noise-free part; the problem adds the noise (it depends on the instance).
double quartic(std::span<const double> z) {
    double sum = 0.0;
    for (std::size_t i = 0; i < z.size(); ++i) {
        const double sq = z[i] * z[i];
        sum += static_cast<double>(i + 1) * sq * sq;
    }
    return sum;
}

double rosenbrock(std::span<const double> z) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < z.size(); ++i) {
        const double a = z[i + 1] - z[i] * z[i];
        const double b = z[i] - 1.0;
        sum += 100.0 * a * a + b * b;
    }
    return sum;
}

double zakharov(std::span<const double> z) {
    double squares = 0.0;
    double weighted = 0.0;
    for (std::size_t i = 0; i < z.size(); ++i) {
        squares += z[i] * z[i];
        weighted += 0.5 * static_cast<double>(i + 1) * z[i];
    }
    const double w2 = weighted * weighted;
    return squares + w2 + w2 * w2;
}

ClassicEvaluator ellipsoid(Eigen::Index dimension) {
    // Weights 10^(6 (i-1)/(D-1)), computed once per dimension (1 when D = 1).
    std::vector<double> weights(static_cast<std::size_t>(dimension), 1.0);
    for (Eigen::Index i = 1; i < dimension; ++i)
        weights[static_cast<std::size_t>(i)] =
            std::pow(1.0e6, static_cast<double>(i) / static_cast<double>(dimension - 1));
    return [weights = std::move(weights)](std::span<const double> z) {
        double sum = 0.0;
        for (std::size_t i = 0; i < z.size(); ++i)
            sum += weights[i] * z[i] * z[i];
        return sum;
    };
}

} // namespace

std::vector<ClassicFunction> classic_unimodal_functions() {
    std::vector<ClassicFunction> list;
    list.push_back({"sphere", "sum z_i^2; separable, unimodal, f* = 0 at the origin", "De Jong (1975)", -100,
                    100, 0, 1, false, stateless<sphere>});
    list.push_back(
        {"ellipsoid",
         "sum 10^(6 (i-1)/(D-1)) z_i^2; high-conditioned (10^6) elliptic, separable, unimodal, f* = 0 at 0",
         "Liang, Qu, Suganthan (2013), CEC 2014 definitions (high conditioned elliptic)", -100, 100, 0, 1,
         false, ellipsoid});
    list.push_back({"schwefel_1_2", "sum_i (sum_{j<=i} z_j)^2; non-separable, unimodal, f* = 0 at 0",
                    "Schwefel (1981); Yao, Liu, Lin (1999) f3", -100, 100, 0, 1, false,
                    stateless<schwefel_1_2>});
    list.push_back({"schwefel_2_21", "max_i |z_i|; non-smooth, unimodal, f* = 0 at 0",
                    "Schwefel (1981); Yao, Liu, Lin (1999) f4", -100, 100, 0, 1, false,
                    stateless<schwefel_2_21>});
    list.push_back({"schwefel_2_22", "sum |z_i| + prod |z_i|; non-smooth, unimodal, f* = 0 at 0",
                    "Schwefel (1981); Yao, Liu, Lin (1999) f2", -10, 10, 0, 1, false,
                    stateless<schwefel_2_22>});
    list.push_back({"step", "sum floor(z_i + 0.5)^2; plateaus, discontinuous, f* = 0 on [-0.5, 0.5)^D",
                    "De Jong (1975); Yao, Liu, Lin (1999) f6", -100, 100, 0, 1, false, stateless<step>});
    list.push_back(
        {"quartic",
         "sum i z_i^4 + noise U[0, 1); noise a deterministic hash of (instance, x), f* = 0 (noise-free) at 0",
         "De Jong (1975); Yao, Liu, Lin (1999) f7", -1.28, 1.28, 0, 1, true, stateless<quartic>});
    list.push_back(
        {"rosenbrock", "sum 100 (z_{i+1} - z_i^2)^2 + (z_i - 1)^2; curved valley, f* = 0 at (1, ..., 1)",
         "Rosenbrock (1960); Yao, Liu, Lin (1999) f5", -30, 30, 1, 2, false, stateless<rosenbrock>});
    list.push_back({"zakharov", "sum z_i^2 + (sum i z_i / 2)^2 + (sum i z_i / 2)^4; unimodal, f* = 0 at 0",
                    "Zakharov; box [-5, 10] as in Jamil and Yang (2013)", -5, 10, 0, 1, false,
                    stateless<zakharov>});
    return list;
}

} // namespace mhb
