// The multimodal classic functions. Formulas and usual boxes as in Yao, Liu and Lin (1999),
// "Evolutionary programming made faster", IEEE TEVC 3(2), table I (f8-f13), unless named otherwise.
#include <array>
#include <cmath>
#include <numbers>

#include "problems/functions/classic_function.hpp"

namespace mhb {
namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

double rastrigin(std::span<const double> z) {
    double sum = 0.0;
    for (const double v : z)
        sum += v * v - 10.0 * std::cos(two_pi * v);
    return 10.0 * static_cast<double>(z.size()) + sum;
}

double ackley(std::span<const double> z) {
    double squares = 0.0;
    double cosines = 0.0;
    for (const double v : z) {
        squares += v * v;
        cosines += std::cos(two_pi * v);
    }
    const double d = static_cast<double>(z.size());
    return -20.0 * std::exp(-0.2 * std::sqrt(squares / d)) - std::exp(cosines / d) + 20.0 + std::numbers::e;
}

double griewank(std::span<const double> z) {
    double squares = 0.0;
    double product = 1.0;
    for (std::size_t i = 0; i < z.size(); ++i) {
        squares += z[i] * z[i];
        product *= std::cos(z[i] / std::sqrt(static_cast<double>(i + 1)));
    }
    return 1.0 + squares / 4000.0 - product;
}

// Schwefel 2.26 shifted up so that f* = 0: sum (c - z_i sin(sqrt|z_i|)), with c the maximum of
// y sin(sqrt y), 418.98288727243374 at y = 420.9687463599821 (both from Newton's method on
// sin(s) + s/2 cos(s) = 0, s = sqrt y). Outside [-500, 500] z_i is folded back and penalised as in
// the CEC 2014 definitions (Liang, Qu, Suganthan 2013), so that a shifted or rotated variant,
// whose z leaves the box, keeps its global optimum at the instance's optimum.
constexpr double schwefel_peak = 418.98288727243374;
constexpr double schwefel_argmax = 420.9687463599821;

double schwefel_2_26(std::span<const double> z) {
    const double d = static_cast<double>(z.size());
    double sum = 0.0;
    for (const double v : z) {
        if (v > 500.0) {
            const double folded = 500.0 - std::fmod(v, 500.0);
            const double excess = (v - 500.0) / 100.0;
            sum += schwefel_peak - folded * std::sin(std::sqrt(folded)) + excess * excess / d;
        } else if (v < -500.0) {
            const double folded = std::fmod(std::fabs(v), 500.0) - 500.0;
            const double excess = (v + 500.0) / 100.0;
            sum += schwefel_peak - folded * std::sin(std::sqrt(std::fabs(folded))) + excess * excess / d;
        } else {
            sum += schwefel_peak - v * std::sin(std::sqrt(std::fabs(v)));
        }
    }
    return sum;
}

double levy(std::span<const double> z) {
    // w_i = 1 + (z_i - 1) / 4.
    const auto w = [&](std::size_t i) { return 1.0 + (z[i] - 1.0) / 4.0; };
    const std::size_t n = z.size();
    const double s1 = std::sin(std::numbers::pi * w(0));
    double sum = s1 * s1;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const double wi = w(i);
        const double s = std::sin(std::numbers::pi * wi + 1.0);
        sum += (wi - 1.0) * (wi - 1.0) * (1.0 + 10.0 * s * s);
    }
    const double wd = w(n - 1);
    const double sd = std::sin(two_pi * wd);
    return sum + (wd - 1.0) * (wd - 1.0) * (1.0 + sd * sd);
}

// Weierstrass with a = 0.5, b = 3, k_max = 20 (CEC 2005 F11):
// sum_i sum_k a^k cos(2 pi b^k (z_i + 0.5)) - D sum_k a^k cos(pi b^k).
constexpr std::size_t weierstrass_terms = 21;

struct WeierstrassTable {
    std::array<double, weierstrass_terms> a{};
    std::array<double, weierstrass_terms> two_pi_b{};
    double offset = 0.0; // sum_k a^k cos(pi b^k)
};

const WeierstrassTable& weierstrass_table() {
    static const WeierstrassTable table = [] {
        WeierstrassTable t;
        for (std::size_t k = 0; k < weierstrass_terms; ++k) {
            t.a[k] = std::pow(0.5, static_cast<double>(k));
            t.two_pi_b[k] = two_pi * std::pow(3.0, static_cast<double>(k));
            t.offset += t.a[k] * std::cos(t.two_pi_b[k] * 0.5);
        }
        return t;
    }();
    return table;
}

double weierstrass(std::span<const double> z) {
    const WeierstrassTable& t = weierstrass_table();
    double sum = 0.0;
    for (const double v : z) {
        // The value at the optimum, 0, cancels the offset term by term, so f* is 0 to the bit.
        for (std::size_t k = 0; k < weierstrass_terms; ++k)
            sum += t.a[k] * std::cos(t.two_pi_b[k] * (v + 0.5));
        sum -= t.offset;
    }
    return sum;
}

// u(x, a, k, m) of Yao, Liu and Lin: k (|x| - a)^m outside [-a, a], 0 inside.
double boundary_penalty(double x, double a, double k) {
    if (x > a)
        return k * std::pow(x - a, 4.0);
    if (x < -a)
        return k * std::pow(-x - a, 4.0);
    return 0.0;
}

double penalized_1(std::span<const double> z) {
    const auto y = [&](std::size_t i) { return 1.0 + (z[i] + 1.0) / 4.0; };
    const std::size_t n = z.size();
    const double s1 = std::sin(std::numbers::pi * y(0));
    double inner = 10.0 * s1 * s1;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const double s = std::sin(std::numbers::pi * y(i + 1));
        inner += (y(i) - 1.0) * (y(i) - 1.0) * (1.0 + 10.0 * s * s);
    }
    inner += (y(n - 1) - 1.0) * (y(n - 1) - 1.0);
    double penalty = 0.0;
    for (const double v : z)
        penalty += boundary_penalty(v, 10.0, 100.0);
    return std::numbers::pi / static_cast<double>(n) * inner + penalty;
}

double penalized_2(std::span<const double> z) {
    const std::size_t n = z.size();
    const double s1 = std::sin(3.0 * std::numbers::pi * z[0]);
    double inner = s1 * s1;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const double s = std::sin(3.0 * std::numbers::pi * z[i + 1]);
        inner += (z[i] - 1.0) * (z[i] - 1.0) * (1.0 + s * s);
    }
    const double sd = std::sin(two_pi * z[n - 1]);
    inner += (z[n - 1] - 1.0) * (z[n - 1] - 1.0) * (1.0 + sd * sd);
    double penalty = 0.0;
    for (const double v : z)
        penalty += boundary_penalty(v, 5.0, 100.0);
    return 0.1 * inner + penalty;
}

} // namespace

std::vector<ClassicFunction> classic_multimodal_functions() {
    std::vector<ClassicFunction> list;
    list.push_back(
        {"rastrigin", "10 D + sum z_i^2 - 10 cos(2 pi z_i); separable, ~10^D local minima, f* = 0 at 0",
         "Rastrigin (1974); Yao, Liu, Lin (1999) f9", -5.12, 5.12, 0, 1, false, stateless<rastrigin>});
    list.push_back(
        {"ackley",
         "-20 exp(-0.2 sqrt(mean z_i^2)) - exp(mean cos(2 pi z_i)) + 20 + e; multimodal, f* = 0 at 0",
         "Ackley (1987); Yao, Liu, Lin (1999) f10", -32, 32, 0, 1, false, stateless<ackley>});
    list.push_back({"griewank", "1 + sum z_i^2 / 4000 - prod cos(z_i / sqrt(i)); multimodal, f* = 0 at 0",
                    "Griewank (1981); Yao, Liu, Lin (1999) f11", -600, 600, 0, 1, false,
                    stateless<griewank>});
    list.push_back({"schwefel_2_26",
                    "sum 418.98288727 - z_i sin(sqrt|z_i|) (CEC 2014 folding beyond +-500); deceptive, "
                    "f* = 0 at (420.96874636, ...)",
                    "Schwefel (1981); Yao, Liu, Lin (1999) f8, shifted to f* = 0; folding from Liang, Qu, "
                    "Suganthan (2013)",
                    -500, 500, schwefel_argmax, 1, false, stateless<schwefel_2_26>});
    list.push_back(
        {"levy",
         "sin^2(pi w_1) + sum (w_i - 1)^2 (1 + 10 sin^2(pi w_i + 1)) + (w_D - 1)^2 (1 + sin^2(2 pi w_D)), "
         "w = 1 + (z - 1)/4; f* = 0 at (1, ..., 1)",
         "Levy and Montalvo (1985); as in Surjanovic and Bingham's library", -10, 10, 1, 1, false,
         stateless<levy>});
    list.push_back({"weierstrass",
                    "sum_i sum_{k=0}^{20} 0.5^k cos(2 pi 3^k (z_i + 0.5)) - D sum_k 0.5^k cos(pi 3^k); "
                    "continuous, nowhere differentiable, f* = 0 at 0",
                    "Suganthan et al. (2005), CEC 2005 definitions F11", -0.5, 0.5, 0, 1, false,
                    stateless<weierstrass>});
    list.push_back({"penalized_1",
                    "pi/D (10 sin^2(pi y_1) + sum (y_i - 1)^2 (1 + 10 sin^2(pi y_{i+1})) + (y_D - 1)^2) "
                    "+ sum u(z_i, 10, 100, 4), y = 1 + (z + 1)/4; f* = 0 at (-1, ..., -1)",
                    "Yao, Liu, Lin (1999) f12 (generalised penalised function 1)", -50, 50, -1, 1, false,
                    stateless<penalized_1>});
    list.push_back({"penalized_2",
                    "0.1 (sin^2(3 pi z_1) + sum (z_i - 1)^2 (1 + sin^2(3 pi z_{i+1})) + (z_D - 1)^2 (1 + "
                    "sin^2(2 pi z_D))) "
                    "+ sum u(z_i, 5, 100, 4); f* = 0 at (1, ..., 1)",
                    "Yao, Liu, Lin (1999) f13 (generalised penalised function 2)", -50, 50, 1, 1, false,
                    stateless<penalized_2>});
    return list;
}

} // namespace mhb
