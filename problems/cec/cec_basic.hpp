// The basic functions of the CEC 2017 and CEC 2022 suites, as the official C code computes them
// (../shared/cec/README.md, section 4), each an inline function of z: the vector after shift, scale
// and rotation (or one group of a hybrid after its own scale), n entries. Offsets the code adds to z
// in place (Rosenbrock +1, HappyCat/HGBat -1, ...) are added to local copies here.
//
// The arithmetic follows the code's order of operations term by term, with three exceptions that
// change values only at the level of rounding, far below the 1e-10 relative the suites are checked to:
// - what the code recomputes on every call with pow() (the Ellipsoid weights 10^(6i/(n-1)),
//   Weierstrass' a^k and b^k, the Katsuura exponent 10/n^1.2, Lunacek's s and mu1) is computed once
//   into a BasicShape, with the same expressions;
// - pow(t, 0.5) is sqrt(t), pow(t, 2) is t*t, pow(|t|, k) for an integer k is repeated squaring;
// - the sines and cosines of a vector are taken together by a vectorised polynomial with an exact
//   argument reduction (detail::cos_two_pi), at a third of the library's cost.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

namespace mhb::cec {

enum class Basic : std::uint8_t {
    bent_cigar,
    sum_of_different_power,
    zakharov,
    rosenbrock,
    rastrigin,
    schaffer_f7,
    lunacek_bi_rastrigin,
    levy_2017, // w = 1 + (z - 1)/4 (its minimum is not at z = 0: README Q6)
    levy_2022, // w = 1 + z/4
    schwefel,
    ellipsoid,
    discus,
    ackley,
    weierstrass,
    griewank,
    katsuura,
    happycat,
    hgbat,
    griewank_rosenbrock,
    expanded_schaffer_f6,
};

// "Bent Cigar", "Lunacek bi-Rastrigin", ...
std::string_view basic_name(Basic basic);

// The factor the code applies to x - o before rotating (its `sh_rate`), written as the code writes it.
inline double basic_scale(Basic basic) {
    switch (basic) {
    case Basic::rosenbrock:
        return 2.048 / 100.0;
    case Basic::rastrigin:
        return 5.12 / 100.0;
    case Basic::schwefel:
        return 1000.0 / 100.0;
    case Basic::griewank:
        return 600.0 / 100.0;
    case Basic::weierstrass:
        return 0.5 / 100.0;
    case Basic::katsuura:
    case Basic::happycat:
    case Basic::hgbat:
    case Basic::griewank_rosenbrock:
        return 5.0 / 100.0;
    case Basic::lunacek_bi_rastrigin:
        return 10.0 / 100.0;
    default:
        return 1.0;
    }
}

// The largest dimension of the official data; per-call scratch is sized for it.
inline constexpr int max_dimension = 100;

namespace detail {

inline constexpr double pi = 3.1415926535897932384626433832795029;
inline constexpr double two_pi = 2.0 * pi; // the code's `2.0*PI*z` is (2.0*PI)*z
inline constexpr double e = 2.7182818284590452353602874713526625;
inline constexpr int weierstrass_terms = 21; // k = 0...20

// Weierstrass' a^k and b^k (a = 0.5, b = 3: exact powers) and the constant the code subtracts,
// sum_k a^k cos(2 pi b^k 0.5), computed as the code computes it, once for the process.
struct WeierstrassTables {
    std::array<double, weierstrass_terms> a_k{};
    std::array<double, weierstrass_terms> b_k{};
    double constant = 0.0;
};
const WeierstrassTables& weierstrass_tables();

// |t|^k for an integer k >= 1 by repeated squaring (within a few ulps of pow(|t|, k)).
inline double integer_power(double t, int k) {
    double result = 1.0;
    double base = t;
    while (true) {
        if (k & 1)
            result *= base;
        k >>= 1;
        if (k == 0)
            return result;
        base *= base;
    }
}

// sin(x) for |x| <= pi/2 by its Taylor series to x^23 (the remainder is below 1e-23), the
// polynomial in x^2 evaluated by Estrin's scheme: a shorter dependency chain than Horner's.
inline double sin_quadrant(double x) {
    constexpr double c0 = 1.0 / 6.0;                        // 1/3!
    constexpr double c1 = -1.0 / 120.0;                     // 1/5!
    constexpr double c2 = 1.0 / 5040.0;                     // 1/7!
    constexpr double c3 = -1.0 / 362880.0;                  // 1/9!
    constexpr double c4 = 1.0 / 39916800.0;                 // 1/11!
    constexpr double c5 = -1.0 / 6227020800.0;              // 1/13!
    constexpr double c6 = 1.0 / 1307674368000.0;            // 1/15!
    constexpr double c7 = -1.0 / 355687428096000.0;         // 1/17!
    constexpr double c8 = 1.0 / 121645100408832000.0;       // 1/19!
    constexpr double c9 = -1.0 / 51090942171709440000.0;    // 1/21!
    constexpr double c10 = 1.0 / 25852016738884976640000.0; // 1/23!
    const double y = x * x;
    const double y2 = y * y;
    const double y4 = y2 * y2;
    const double y8 = y4 * y4;
    const double p03 = (c0 + c1 * y) + (c2 + c3 * y) * y2;
    const double p47 = (c4 + c5 * y) + (c6 + c7 * y) * y2;
    const double p810 = (c8 + c9 * y) + c10 * y2;
    const double p = p03 + p47 * y4 + p810 * y8;
    return x - x * y * p;
}

// cos(2 pi u) for |u| < 2^50, without the check. u - round(u) is exact, so the reduction adds
// no error; (u + 1.5 2^52) - 1.5 2^52 is u rounded to an integer for |u| < 2^51 (IEEE arithmetic
// without -ffast-math, as everywhere in this project). Then cos(2 pi r) = cos(2 pi |r|)
// = -sin(2 pi (|r| - 1/4)), whose argument lies within [-pi/2, pi/2].
inline double cos_two_pi_unchecked(double u) {
    constexpr double round_magic = 6755399441055744.0;
    const double r = u - ((u + round_magic) - round_magic); // in [-1/2, 1/2]
    return -sin_quadrant(two_pi * (std::fabs(r) - 0.25));
}

// Below this many values the library's sin and cos are faster: too few values to hide the
// polynomial's latency.
inline constexpr int vector_trig_minimum = 4;

// out[i] = cos(2 pi u[i]): the terms cos(2.0*PI*z) of Rastrigin, Ackley, Lunacek and Weierstrass.
// The code's cos(fl(2 pi u)) differs from the true value by up to |2 pi u| ulp, and from this by
// as much (7e-13 at |u| = 1000): far below the 1e-10 relative the suites are checked to. The loop
// vectorises (no calls, no branches) and costs a third of the library's cos; |u| >= 2^50,
// infinities and NaNs go through std::cos as the code's would.
inline void cos_two_pi(const double* u, double* out, int n) {
    if (n < vector_trig_minimum) {
        for (int i = 0; i < n; ++i)
            out[i] = std::cos(two_pi * u[i]);
        return;
    }
    for (int i = 0; i < n; ++i)
        out[i] = cos_two_pi_unchecked(u[i]);
    for (int i = 0; i < n; ++i)
        if (!(std::fabs(u[i]) < 0x1p50))
            out[i] = std::cos(two_pi * u[i]);
}

// out[i] = cos(x[i] - phase) through cos_two_pi_unchecked(x / 2 pi - phase / 2 pi), or
// library(x[i]) where that does not apply. Dividing by 2 pi errs by |x| 2e-16 in the phase, twice
// the error the code's own argument x carries (rounded once when computed): 2e-14 at the largest
// sqrt|z| of Schwefel, well below 1e-10 of F.
template <class Library>
inline void cos_shifted(const double* x, double* out, int n, double phase_turns, Library library) {
    if (n < vector_trig_minimum) {
        for (int i = 0; i < n; ++i)
            out[i] = library(x[i]);
        return;
    }
    constexpr double inverse_two_pi = 1.0 / two_pi;
    for (int i = 0; i < n; ++i)
        out[i] = cos_two_pi_unchecked(x[i] * inverse_two_pi - phase_turns);
    for (int i = 0; i < n; ++i)
        if (!(std::fabs(x[i]) < 0x1p50))
            out[i] = library(x[i]);
}

// out[i] = sin(x[i]) (a cosine a quarter turn later) and cos(x[i]).
inline void sin_of(const double* x, double* out, int n) {
    cos_shifted(x, out, n, 0.25, [](double v) { return std::sin(v); });
}

inline void cos_of(const double* x, double* out, int n) {
    cos_shifted(x, out, n, 0.0, [](double v) { return std::cos(v); });
}

} // namespace detail

inline double bent_cigar(const double* z, int n) {
    double f = z[0] * z[0];
    for (int i = 1; i < n; ++i)
        f += 1e6 * z[i] * z[i];
    return f;
}

inline double discus(const double* z, int n) {
    double f = 1e6 * z[0] * z[0];
    for (int i = 1; i < n; ++i)
        f += z[i] * z[i];
    return f;
}

// weights[i] = pow(10.0, 6.0*i/(n-1)).
inline double ellipsoid(const double* z, int n, const double* weights) {
    double f = 0.0;
    for (int i = 0; i < n; ++i)
        f += weights[i] * z[i] * z[i];
    return f;
}

// sum |z_i|^(i+1), with the real absolute value (README Q8).
inline double sum_of_different_power(const double* z, int n) {
    double f = 0.0;
    for (int i = 0; i < n; ++i)
        f += detail::integer_power(std::fabs(z[i]), i + 1);
    return f;
}

inline double zakharov(const double* z, int n) {
    double sum1 = 0.0;
    double sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        sum1 += z[i] * z[i];
        sum2 += 0.5 * (i + 1) * z[i];
    }
    const double square = sum2 * sum2;
    return sum1 + square + square * square;
}

// The code adds 1 to z in place; the sums here are the same, on local copies (writing z back and
// reading it in the next iteration costs a store-forwarding stall once vectorised).
inline double rosenbrock(const double* z, int n) {
    double f = 0.0;
    double current = z[0] + 1.0;
    for (int i = 0; i < n - 1; ++i) {
        const double next = z[i + 1] + 1.0;
        const double t1 = current * current - next;
        const double t2 = current - 1.0;
        f += 100.0 * t1 * t1 + t2 * t2;
        current = next;
    }
    return f;
}

inline double rastrigin(const double* z, int n) {
    double f = 0.0;
    if (n < detail::vector_trig_minimum) {
        for (int i = 0; i < n; ++i)
            f += z[i] * z[i] - 10.0 * std::cos(detail::two_pi * z[i]) + 10.0;
        return f;
    }
    std::array<double, max_dimension> cosine;
    detail::cos_two_pi(z, cosine.data(), n);
    for (int i = 0; i < n; ++i)
        f += z[i] * z[i] - 10.0 * cosine[static_cast<std::size_t>(i)] + 10.0;
    return f;
}

// The code's Schaffer F7 reads y (the vector before rotation), never z: README Q1, Q2.
inline double schaffer_f7(const double* y, int n) {
    double f = 0.0;
    for (int i = 0; i < n - 1; ++i) {
        const double s = std::sqrt(y[i] * y[i] + y[i + 1] * y[i + 1]);
        const double t = std::sin(50.0 * std::pow(s, 0.2));
        const double root = std::sqrt(s);
        f += root + root * t * t;
    }
    return f * f / (n - 1) / (n - 1);
}

// Lunacek bi-Rastrigin (README Q4, Q5): z_hat = 2 y with the sign of o, `cosine_of` = M z_hat
// (standalone) or z_hat itself (inside a hybrid); s and mu1 as BasicShape computes them.
inline double lunacek_bi_rastrigin(const double* z_hat, const double* cosine_of, int n, double s,
                                   double mu1) {
    constexpr double mu0 = 2.5;
    double sum0 = 0.0;
    double sum1 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = z_hat[i] + mu0; // as the code: (z + mu0) - mu0, (z + mu0) - mu1
        sum0 += (t - mu0) * (t - mu0);
        sum1 += (t - mu1) * (t - mu1);
    }
    sum1 = sum1 * s + 1.0 * n;
    std::array<double, max_dimension> cosine;
    detail::cos_two_pi(cosine_of, cosine.data(), n);
    double cosines = 0.0;
    for (int i = 0; i < n; ++i)
        cosines += cosine[static_cast<std::size_t>(i)];
    return (sum0 < sum1 ? sum0 : sum1) + 10.0 * (n - cosines);
}

// offset 1 for CEC 2017 (w = 1 + (z - 1)/4), 0 for CEC 2022 (README Q6).
inline double levy(const double* z, int n, double offset) {
    const auto w = [&](int i) { return 1.0 + (z[i] - offset) / 4.0; };
    const double w0 = w(0);
    const double wn = w(n - 1);
    const double s0 = std::sin(detail::pi * w0);
    const double sn = std::sin(detail::two_pi * wn);
    const double term1 = s0 * s0;
    const double term3 = (wn - 1) * (wn - 1) * (1 + sn * sn);
    const auto term = [](double wi, double s) { return (wi - 1) * (wi - 1) * (1 + 10 * s * s); };
    double sum = 0.0;
    if (n - 1 < detail::vector_trig_minimum) {
        for (int i = 0; i < n - 1; ++i)
            sum += term(w(i), std::sin(detail::pi * w(i) + 1));
        return term1 + sum + term3;
    }
    std::array<double, max_dimension> argument;
    std::array<double, max_dimension> sine;
    for (int i = 0; i < n - 1; ++i)
        argument[static_cast<std::size_t>(i)] = detail::pi * w(i) + 1;
    detail::sin_of(argument.data(), sine.data(), n - 1);
    for (int i = 0; i < n - 1; ++i)
        sum += term(w(i), sine[static_cast<std::size_t>(i)]);
    return term1 + sum + term3;
}

// The modified Schwefel function of the CEC suites, with its out-of-range penalty. Each term is
// factor * sin(sqrt(root)), gathered first so that the sines are taken together; the penalties
// are summed apart (a reordering of the code's single sum).
inline double schwefel(const double* z, int n) {
    std::array<double, max_dimension> factor;
    std::array<double, max_dimension> root;
    std::array<double, max_dimension> sine;
    double penalty = 0.0;
    for (int i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const double t = z[i] + 4.209687462275036e+002;
        if (t > 500) {
            const double folded = 500.0 - std::fmod(t, 500);
            factor[k] = folded;
            root[k] = std::sqrt(folded);
            const double excess = (t - 500.0) / 100;
            penalty += excess * excess / n;
        } else if (t < -500) {
            const double rest = std::fmod(std::fabs(t), 500);
            factor[k] = -500.0 + rest;
            root[k] = std::sqrt(500.0 - rest);
            const double excess = (t + 500.0) / 100;
            penalty += excess * excess / n;
        } else {
            factor[k] = t;
            root[k] = std::sqrt(std::fabs(t));
        }
    }
    detail::sin_of(root.data(), sine.data(), n);
    double f = 0.0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k)
        f -= factor[k] * sine[k];
    return f + penalty + 4.189828872724338e+002 * n;
}

inline double ackley(const double* z, int n) {
    std::array<double, max_dimension> cosine;
    detail::cos_two_pi(z, cosine.data(), n);
    double sum1 = 0.0;
    double sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        sum1 += z[i] * z[i];
        sum2 += cosine[static_cast<std::size_t>(i)];
    }
    sum1 = -0.2 * std::sqrt(sum1 / n);
    sum2 /= n;
    return detail::e - 20.0 * std::exp(sum1) - std::exp(sum2) + 20.0;
}

// The code's cos(2.0*PI*pow(b,k)*(z+0.5)) is cos(2 pi u) with u = b^k (z + 0.5).
inline double weierstrass(const double* z, int n) {
    const auto& tables = detail::weierstrass_tables();
    constexpr auto terms = static_cast<std::size_t>(detail::weierstrass_terms);
    double f = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = z[i] + 0.5;
        std::array<double, terms> u;
        std::array<double, terms> cosine;
        for (std::size_t k = 0; k < terms; ++k)
            u[k] = tables.b_k[k] * t;
        detail::cos_two_pi(u.data(), cosine.data(), detail::weierstrass_terms);
        double sum = 0.0;
        for (std::size_t k = 0; k < terms; ++k)
            sum += tables.a_k[k] * cosine[k];
        f += sum;
    }
    return f - n * tables.constant;
}

// roots[i] = sqrt(1.0 + i).
inline double griewank(const double* z, int n, const double* roots) {
    std::array<double, max_dimension> argument;
    std::array<double, max_dimension> cosine;
    for (int i = 0; i < n; ++i)
        argument[static_cast<std::size_t>(i)] = z[i] / roots[i];
    detail::cos_of(argument.data(), cosine.data(), n);
    double s = 0.0;
    double p = 1.0;
    for (int i = 0; i < n; ++i) {
        s += z[i] * z[i];
        p *= cosine[static_cast<std::size_t>(i)];
    }
    return 1.0 + s / 4000.0 - p;
}

// exponent = 10.0/pow(1.0*n, 1.2), factor = 10.0/n/n.
inline double katsuura(const double* z, int n, double exponent, double factor) {
    double f = 1.0;
    for (int i = 0; i < n; ++i) {
        double sum = 0.0;
        double power = 1.0; // 2^j, exact
        double inverse = 1.0;
        for (int j = 1; j <= 32; ++j) {
            power *= 2.0;
            inverse *= 0.5; // dividing by 2^j is multiplying by 2^-j, exactly
            const double t = power * z[i];
            sum += std::fabs(t - std::floor(t + 0.5)) * inverse;
        }
        f *= std::pow(1.0 + (i + 1) * sum, exponent);
    }
    return f * factor - factor;
}

// HappyCat and HGBat on z - 1.
inline double happycat(const double* z, int n) {
    double r2 = 0.0;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = z[i] - 1.0;
        r2 += t * t;
        sum += t;
    }
    return std::sqrt(std::sqrt(std::fabs(r2 - n))) + (0.5 * r2 + sum) / n + 0.5;
}

inline double hgbat(const double* z, int n) {
    double r2 = 0.0;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = z[i] - 1.0;
        r2 += t * t;
        sum += t;
    }
    return std::sqrt(std::fabs(r2 * r2 - sum * sum)) + (0.5 * r2 + sum) / n + 0.5;
}

// Pairs (z_i + 1, z_(i+1) + 1), then the wrap-around pair (z_(n-1) + 1, z_0 + 1): each term is
// t^2/4000 - cos(t) + 1 with t the pair's Rosenbrock value.
inline double griewank_rosenbrock(const double* z, int n) {
    std::array<double, max_dimension> t;
    std::array<double, max_dimension> cosine;
    for (int i = 0; i < n; ++i) {
        const double a = z[i] + 1.0;
        const double b = (i + 1 < n ? z[i + 1] : z[0]) + 1.0;
        const double t1 = a * a - b;
        const double t2 = a - 1.0;
        t[static_cast<std::size_t>(i)] = 100.0 * t1 * t1 + t2 * t2;
    }
    detail::cos_of(t.data(), cosine.data(), n);
    double f = 0.0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i)
        f += t[i] * t[i] / 4000.0 - cosine[i] + 1.0;
    return f;
}

// Pairs (z_i, z_(i+1)), then the wrap-around pair (z_(n-1), z_0).
inline double expanded_schaffer_f6(const double* z, int n) {
    std::array<double, max_dimension> r2;
    std::array<double, max_dimension> root;
    std::array<double, max_dimension> sine;
    for (int i = 0; i < n; ++i) {
        const double b = i + 1 < n ? z[i + 1] : z[0];
        r2[static_cast<std::size_t>(i)] = z[i] * z[i] + b * b;
        root[static_cast<std::size_t>(i)] = std::sqrt(r2[static_cast<std::size_t>(i)]);
    }
    detail::sin_of(root.data(), sine.data(), n);
    double f = 0.0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
        const double s = sine[i] * sine[i];
        const double d = 1.0 + 0.001 * r2[i];
        f += 0.5 + (s - 0.5) / (d * d);
    }
    return f;
}

// A basic function bound to a length n, with everything the code recomputes per call with pow()
// computed once. Lunacek bi-Rastrigin also keeps the signs of o it flips z by.
class BasicShape {
public:
    // `shift` (n entries or more) is read by Lunacek bi-Rastrigin only (the signs of its first n).
    BasicShape(Basic basic, int n, const double* shift = nullptr);

    [[nodiscard]] Basic basic() const { return basic_; }
    [[nodiscard]] int size() const { return n_; }
    [[nodiscard]] double scale() const { return scale_; }

    // g(z) for z already shifted, scaled and rotated (Schaffer F7: y, unrotated); z is scratch
    // (Lunacek bi-Rastrigin flips its signs in place).
    // Lunacek bi-Rastrigin: z is the scaled y; the cosine term reads 2 y sign(o) itself (as in a
    // hybrid); the standalone function, whose cosine term is rotated, uses lunacek_* below.
    double operator()(double* z) const;

    // Lunacek bi-Rastrigin in two steps: y -> z_hat = 2 y sign(o) in place, then g given M z_hat.
    void lunacek_flip(double* y) const;
    [[nodiscard]] double lunacek_value(const double* z_hat, const double* rotated) const {
        return lunacek_bi_rastrigin(z_hat, rotated, n_, c0_, c1_);
    }

private:
    Basic basic_;
    int n_;
    double scale_;
    std::vector<double> table_; // Ellipsoid weights, Griewank roots, Lunacek signs
    double c0_ = 0.0;           // Katsuura exponent, Lunacek s, Levy offset
    double c1_ = 0.0;           // Katsuura factor, Lunacek mu1
};

inline double BasicShape::operator()(double* z) const {
    const int n = n_;
    switch (basic_) {
    case Basic::bent_cigar:
        return bent_cigar(z, n);
    case Basic::sum_of_different_power:
        return sum_of_different_power(z, n);
    case Basic::zakharov:
        return zakharov(z, n);
    case Basic::rosenbrock:
        return rosenbrock(z, n);
    case Basic::rastrigin:
        return rastrigin(z, n);
    case Basic::schaffer_f7:
        return schaffer_f7(z, n);
    case Basic::lunacek_bi_rastrigin:
        lunacek_flip(z);
        return lunacek_bi_rastrigin(z, z, n, c0_, c1_);
    case Basic::levy_2017:
    case Basic::levy_2022:
        return levy(z, n, c0_);
    case Basic::schwefel:
        return schwefel(z, n);
    case Basic::ellipsoid:
        return ellipsoid(z, n, table_.data());
    case Basic::discus:
        return discus(z, n);
    case Basic::ackley:
        return ackley(z, n);
    case Basic::weierstrass:
        return weierstrass(z, n);
    case Basic::griewank:
        return griewank(z, n, table_.data());
    case Basic::katsuura:
        return katsuura(z, n, c0_, c1_);
    case Basic::happycat:
        return happycat(z, n);
    case Basic::hgbat:
        return hgbat(z, n);
    case Basic::griewank_rosenbrock:
        return griewank_rosenbrock(z, n);
    case Basic::expanded_schaffer_f6:
        return expanded_schaffer_f6(z, n);
    }
    return 0.0; // unreachable: every enumerator is handled above
}

inline void BasicShape::lunacek_flip(double* y) const {
    for (int i = 0; i < n_; ++i)
        y[i] = 2 * y[i] * table_[static_cast<std::size_t>(i)];
}

} // namespace mhb::cec
