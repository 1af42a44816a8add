#include "results/analysis/uniformity_tests.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mhb {
namespace {

void check_unit_sample(const std::vector<double>& sample, const char* test) {
    if (sample.empty())
        throw std::invalid_argument(std::string(test) + ": the sample is empty");
    for (double v : sample)
        if (!(v >= 0.0 && v <= 1.0))
            throw std::invalid_argument(std::string(test) + ": a value outside [0, 1] (" + std::to_string(v) +
                                        ")");
}

// A square matrix, row-major (results/ needs no linear-algebra library for this one product).
struct SquareMatrix {
    std::size_t m = 0;
    std::vector<double> a;

    explicit SquareMatrix(std::size_t size) : m(size), a(size * size, 0.0) {}
    double& operator()(std::size_t i, std::size_t j) { return a[i * m + j]; }
    double operator()(std::size_t i, std::size_t j) const { return a[i * m + j]; }
};

SquareMatrix product(const SquareMatrix& x, const SquareMatrix& y) {
    SquareMatrix z(x.m);
    for (std::size_t i = 0; i < x.m; ++i)
        for (std::size_t k = 0; k < x.m; ++k)
            for (std::size_t j = 0; j < x.m; ++j)
                z(i, j) += x(i, k) * y(k, j);
    return z;
}

// A matrix power that keeps its scale apart, as Marsaglia, Tsang and Wang's mPower does: the
// entries of H^n overflow a double long before n = 100.
struct ScaledMatrix {
    SquareMatrix m;
    int exponent10 = 0; // the value is m * 10^exponent10
};

ScaledMatrix scaled_power(const SquareMatrix& h, std::size_t n) {
    if (n == 1)
        return {h, 0};
    const ScaledMatrix half = scaled_power(h, n / 2);
    ScaledMatrix result{product(half.m, half.m), 2 * half.exponent10};
    if (n % 2 == 1)
        result.m = product(h, result.m);
    const std::size_t centre = h.m / 2;
    if (result.m(centre, centre) > 1e140) {
        for (double& v : result.m.a)
            v *= 1e-140;
        result.exponent10 += 140;
    }
    return result;
}

// P(D_n < d) by Marsaglia, Tsang and Wang's (2003) exact matrix method: k = floor(n d) + 1,
// h = k - n d, H the (2k - 1)-square matrix of their eq. (2); P = n! / n^n (H^n)_{kk}.
double kolmogorov_cdf_matrix(std::size_t n, double d) {
    const double nd = static_cast<double>(n) * d;
    const auto k = static_cast<std::size_t>(std::floor(nd)) + 1;
    const std::size_t m = 2 * k - 1;
    const double h = static_cast<double>(k) - nd;
    SquareMatrix matrix(m);
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j <= i + 1 && j < m; ++j)
            matrix(i, j) = 1.0;
    for (std::size_t i = 0; i < m; ++i) {
        matrix(i, 0) -= std::pow(h, static_cast<double>(i + 1));
        matrix(m - 1, i) -= std::pow(h, static_cast<double>(m - i));
    }
    matrix(m - 1, 0) += 2.0 * h - 1.0 > 0.0 ? std::pow(2.0 * h - 1.0, static_cast<double>(m)) : 0.0;
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j <= i; ++j)
            for (std::size_t g = 2; g <= i - j + 1; ++g)
                matrix(i, j) /= static_cast<double>(g);
    const ScaledMatrix power = scaled_power(matrix, n);
    double s = power.m(k - 1, k - 1);
    int exponent10 = power.exponent10;
    for (std::size_t i = 1; i <= n; ++i) {
        s = s * static_cast<double>(i) / static_cast<double>(n);
        if (s < 1e-140) {
            s *= 1e140;
            exponent10 -= 140;
        }
    }
    return s * std::pow(10.0, exponent10);
}

// P(D+_n >= d), exactly (Birnbaum and Tingey 1951): d sum_{j=0}^{floor(n(1-d))} C(n, j)
// (1 - d - j/n)^(n-j) (d + j/n)^(j-1); every term is positive, each computed by its logarithm.
double smirnov_upper_tail(std::size_t n, double d) {
    if (d >= 1.0)
        return 0.0;
    const double nn = static_cast<double>(n);
    const auto last = static_cast<std::size_t>(std::floor(nn * (1.0 - d)));
    double sum = 0.0;
    for (std::size_t j = 0; j <= last && j <= n; ++j) {
        const double jj = static_cast<double>(j);
        const double below = 1.0 - d - jj / nn;
        if (below <= 0.0 && j < n)
            continue; // 0^(n-j) = 0
        const double log_term = std::lgamma(nn + 1.0) - std::lgamma(jj + 1.0) - std::lgamma(nn - jj + 1.0) +
                                (j < n ? (nn - jj) * std::log(below) : 0.0) +
                                (jj - 1.0) * std::log(d + jj / nn);
        sum += std::exp(log_term);
    }
    return std::min(1.0, d * sum);
}

// Marsaglia and Marsaglia's (2004) short ADinf: P(A_inf < z), |error| < 2e-6.
double anderson_darling_limit_cdf(double z) {
    if (z < 2.0)
        return std::exp(-1.2337141 / z) / std::sqrt(z) *
               (2.00012 + (.247105 - (.0649821 - (.0347962 - (.011672 - .00168691 * z) * z) * z) * z) * z);
    return std::exp(
        -std::exp(1.0776 - (2.30695 - (.43424 - (.082433 - (.008056 - .0003146 * z) * z) * z) * z) * z));
}

// Their errfix(n, x): what adds to x = ADinf(z) to give P(A_n < z).
double anderson_darling_finite_n_correction(double n, double x) {
    if (x > .8)
        return (-130.2137 +
                (745.2337 - (1705.091 - (1950.646 - (1116.360 - 255.7844 * x) * x) * x) * x) * x) /
               n;
    const double c = .01265 + .1757 / n;
    if (x < c) {
        double t = x / c;
        t = std::sqrt(t) * (1. - t) * (49 * t - 102);
        return t * (.0037 / (n * n) + .00078 / n + .00006) / n;
    }
    double t = (x - c) / (.8 - c);
    t = -.00022633 + (6.54034 - (14.6538 - (14.458 - (8.259 - 1.91864 * t) * t) * t) * t) * t;
    return t * (.04213 + .01365 / n) / n;
}

} // namespace

double kolmogorov_smirnov_p_value(std::size_t n, double d) {
    if (n == 0)
        throw std::invalid_argument("Kolmogorov-Smirnov: the sample is empty");
    const double nn = static_cast<double>(n);
    if (d <= 0.5 / nn)
        return 1.0; // D_n >= 1/(2n) always
    if (d >= 1.0)
        return 0.0;
    // Beyond these n d^2 the two one-sided tails no longer overlap to double precision (scipy's
    // rules in kstwo.sf: 4 up to n = 140, 2.2 beyond), and 2 P(D+ >= d) is the p-value.
    const double one_sided_from = n <= 140 ? 4.0 : 2.2;
    if (nn * d * d > one_sided_from || d >= 0.5)
        return std::min(1.0, 2.0 * smirnov_upper_tail(n, d));
    return std::clamp(1.0 - kolmogorov_cdf_matrix(n, d), 0.0, 1.0);
}

double anderson_darling_p_value(std::size_t n, double a) {
    if (n == 0)
        throw std::invalid_argument("Anderson-Darling: the sample is empty");
    if (std::isinf(a))
        return 0.0;
    if (a <= 0.0)
        return 1.0;
    const double x = anderson_darling_limit_cdf(a);
    return std::clamp(1.0 - (x + anderson_darling_finite_n_correction(static_cast<double>(n), x)), 0.0, 1.0);
}

UniformityTest kolmogorov_smirnov_uniform(std::vector<double> sample) {
    check_unit_sample(sample, "Kolmogorov-Smirnov");
    std::sort(sample.begin(), sample.end());
    const double n = static_cast<double>(sample.size());
    double d = 0.0;
    for (std::size_t i = 0; i < sample.size(); ++i) {
        const double rank = static_cast<double>(i);
        d = std::max({d, (rank + 1.0) / n - sample[i], sample[i] - rank / n});
    }
    return {d, kolmogorov_smirnov_p_value(sample.size(), d)};
}

// A^2 = -n - (1/n) sum_i (2i - 1) [ln x_(i) + ln(1 - x_(n+1-i))].
UniformityTest anderson_darling_uniform(std::vector<double> sample) {
    check_unit_sample(sample, "Anderson-Darling");
    std::sort(sample.begin(), sample.end());
    const std::size_t n = sample.size();
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        sum += (2.0 * static_cast<double>(i) + 1.0) * (std::log(sample[i]) + std::log1p(-sample[n - 1 - i]));
    const double a = -static_cast<double>(n) - sum / static_cast<double>(n);
    return {a, anderson_darling_p_value(n, a)};
}

} // namespace mhb
