// vector_exp and vector_log against std::exp and std::log: at most 1 ulp apart over the ranges the
// flux map uses (exp of p log x, log of |psi| in (0, 100] and of s^2) and over all doubles, with
// the special values exactly as std's (0, subnormals, infinities, NaN, underflow to 0, overflow to
// infinity), and an element's value independent of its neighbours and of where it sits in the array.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <vector>

#include "problems/core/matrix_vector.hpp"
#include "problems/core/rng.hpp"
#include "problems/core/vector_math.hpp"

namespace mhb {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double quiet_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double min_normal = std::numeric_limits<double>::min();
constexpr double min_subnormal = std::numeric_limits<double>::denorm_min();
constexpr double max_double = std::numeric_limits<double>::max();

// Doubles in increasing order as integers: the number of doubles between a and b.
std::int64_t double_ordinal(double x) {
    const auto bits = std::bit_cast<std::int64_t>(x);
    return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
}

// Ulps between a and b; 0 for two NaNs, "far" for a NaN and a number.
std::int64_t ulp_distance(double a, double b) {
    constexpr std::int64_t far = std::int64_t{1} << 62;
    if (std::isnan(a) || std::isnan(b))
        return std::isnan(a) && std::isnan(b) ? 0 : far;
    if (a == b)
        return 0;
    const std::int64_t d = double_ordinal(a) - double_ordinal(b);
    return d < 0 ? -d : d;
}

enum class Function { exp, log };

std::vector<double> run_kernel(Function f, const std::vector<double>& x) {
    std::vector<double> y(x.size());
    if (f == Function::exp)
        vector_exp(x.data(), y.data(), x.size());
    else
        vector_log(x.data(), y.data(), x.size());
    return y;
}

// The largest distance from std over x, and where.
void expect_within_one_ulp(Function f, const std::vector<double>& x, const std::string& what) {
    const std::vector<double> y = run_kernel(f, x);
    std::int64_t worst = 0;
    double at = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double reference = f == Function::exp ? std::exp(x[i]) : std::log(x[i]);
        const std::int64_t d = ulp_distance(y[i], reference);
        if (d > worst) {
            worst = d;
            at = x[i];
        }
    }
    EXPECT_LE(worst, 1) << what << ": " << worst << " ulps at x = " << at;
}

std::vector<double> uniform_points(Rng& rng, double lo, double hi, int count) {
    std::vector<double> x(static_cast<std::size_t>(count));
    for (double& v : x)
        v = rng.uniform(lo, hi);
    return x;
}

// Every double of the sign's half with equal weight per binade: random bits.
std::vector<double> random_bit_doubles(Rng& rng, bool positive, int count) {
    std::vector<double> x(static_cast<std::size_t>(count));
    for (double& v : x) {
        std::uint64_t bits = rng.next();
        if (positive)
            bits &= ~(std::uint64_t{1} << 63);
        v = std::bit_cast<double>(bits);
    }
    return x;
}

// The doubles next to each of `points`, a few ulps either side.
std::vector<double> neighbours_of(const std::vector<double>& points) {
    std::vector<double> x;
    for (double p : points) {
        double below = p, above = p;
        for (int i = 0; i < 4; ++i) {
            x.push_back(below);
            x.push_back(above);
            below = std::nextafter(below, -infinity);
            above = std::nextafter(above, infinity);
        }
    }
    return x;
}

TEST(VectorMath, ExpIsWithinOneUlpOfStd) {
    Rng rng(35);
    const int n = 200000;
    expect_within_one_ulp(Function::exp, uniform_points(rng, -0.35, 0.35, n), "reduced range");
    expect_within_one_ulp(Function::exp, uniform_points(rng, -60.0, 10.0, n), "p log x of the flux map");
    expect_within_one_ulp(Function::exp, uniform_points(rng, -745.2, 709.8, n), "all finite results");
    expect_within_one_ulp(Function::exp, uniform_points(rng, -760.0, -700.0, n), "subnormal results");
    expect_within_one_ulp(Function::exp, uniform_points(rng, 700.0, 712.0, n), "near overflow");
    expect_within_one_ulp(Function::exp, uniform_points(rng, 500.0, 530.0, n), "both sides of 512");
    expect_within_one_ulp(Function::exp, random_bit_doubles(rng, false, n), "any double");
    // Where the reduction's k changes, and the edges of the results' range.
    expect_within_one_ulp(Function::exp,
                          neighbours_of({0.5 * std::log(2.0), -0.5 * std::log(2.0), 512.0, -512.0,
                                         708.39641853226408, -708.39641853226408, 709.782712893384,
                                         -745.13321910194110, -744.44007192138122, 1080.0, -1080.0}),
                          "edges");
}

TEST(VectorMath, LogIsWithinOneUlpOfStd) {
    Rng rng(36);
    const int n = 200000;
    expect_within_one_ulp(Function::log, uniform_points(rng, 0.0, 100.0, n), "|psi| in (0, 100]");
    expect_within_one_ulp(Function::log, uniform_points(rng, 0.7, 1.42, n), "the reduced range");
    expect_within_one_ulp(Function::log, uniform_points(rng, 0.999, 1.001, n), "near 1");
    expect_within_one_ulp(Function::log, uniform_points(rng, 0.0, 1e4, n), "s^2");
    expect_within_one_ulp(Function::log, random_bit_doubles(rng, true, n), "any positive double");
    expect_within_one_ulp(Function::log, uniform_points(rng, 0.0, 1e3 * min_normal, n), "subnormals");
    expect_within_one_ulp(
        Function::log,
        neighbours_of({1.0, std::sqrt(0.5), std::sqrt(2.0), 2.0, 0.5, min_normal, max_double / 2}), "edges");
}

TEST(VectorMath, SpecialValuesAreStds) {
    const std::vector<double> exp_x = {0.0,    -0.0,          -infinity,     infinity, quiet_nan,
                                       1e300,  -1e300,        709.79,        710.0,    -745.14,
                                       -746.0, min_subnormal, -min_subnormal};
    const std::vector<double> exp_y = run_kernel(Function::exp, exp_x);
    const std::vector<double> exp_expected = {1.0,      1.0,      0.0, infinity, quiet_nan, infinity, 0.0,
                                              infinity, infinity, 0.0, 0.0,      1.0,       1.0};
    for (std::size_t i = 0; i < exp_x.size(); ++i)
        EXPECT_EQ(ulp_distance(exp_y[i], exp_expected[i]), 0) << "exp(" << exp_x[i] << ") = " << exp_y[i];
    EXPECT_FALSE(std::signbit(exp_y[2])) << "exp(-infinity) is +0";

    const std::vector<double> log_x = {1.0,       0.0,  -0.0,           infinity,      -infinity,
                                       quiet_nan, -1.0, -min_subnormal, min_subnormal, max_double};
    const std::vector<double> log_y = run_kernel(Function::log, log_x);
    const std::vector<double> log_expected = {0.0,
                                              -infinity,
                                              -infinity,
                                              infinity,
                                              quiet_nan,
                                              quiet_nan,
                                              quiet_nan,
                                              quiet_nan,
                                              std::log(min_subnormal),
                                              std::log(max_double)};
    for (std::size_t i = 0; i < log_x.size(); ++i)
        EXPECT_EQ(ulp_distance(log_y[i], log_expected[i]), 0) << "log(" << log_x[i] << ") = " << log_y[i];
}

// The main loop and the one-by-one pass for special inputs give each element the same bits, at any
// length (the vectorised loop's remainder) and any position, whatever its neighbours are.
TEST(VectorMath, AnElementsValueDoesNotDependOnItsNeighbours) {
    Rng rng(37);
    for (const Function f : {Function::exp, Function::log}) {
        const double specials[] = {0.0, -infinity, infinity, quiet_nan, 800.0, -800.0, 1e-310};
        std::vector<double> x;
        for (int i = 0; i < 300; ++i)
            x.push_back(rng.uniform() < 0.1  ? specials[rng.next() % 7]
                        : f == Function::exp ? rng.uniform(-40.0, 5.0)
                                             : rng.uniform(0.0, 100.0));
        const std::vector<double> whole = run_kernel(f, x);
        for (std::size_t start = 0; start < 5; ++start)
            for (std::size_t length = 0; start + length <= x.size(); length += 1 + length / 3) {
                const std::vector<double> part(x.begin() + static_cast<std::ptrdiff_t>(start),
                                               x.begin() + static_cast<std::ptrdiff_t>(start + length));
                const std::vector<double> y = run_kernel(f, part);
                for (std::size_t i = 0; i < length; ++i)
                    ASSERT_EQ(std::bit_cast<std::uint64_t>(y[i]),
                              std::bit_cast<std::uint64_t>(whole[start + i]))
                        << (f == Function::exp ? "exp" : "log") << " of " << part[i] << " at " << start << "+"
                        << i;
            }
    }
}

// The AVX2 loops give every element the bits of the SSE2 ones, so that a value does not depend on
// the processor: over all doubles, the flux map's ranges and the special values, at every length
// and alignment (the 4-, 2- and 1-double parts of the loops).
TEST(VectorMath, TheAvx2KernelsEqualTheSse2OnesBitForBit) {
    if (!detail::processor_has_avx2())
        GTEST_SKIP() << "this processor has no AVX2; vector_exp and vector_log use the SSE2 loops";
    Rng rng(38);
    std::vector<double> x = random_bit_doubles(rng, false, 100000);
    for (const double v : uniform_points(rng, -60.0, 10.0, 100000))
        x.push_back(v);
    for (const double v : uniform_points(rng, 0.0, 100.0, 100000))
        x.push_back(v);
    for (const double v :
         {0.0, -0.0, infinity, -infinity, quiet_nan, min_subnormal, max_double, 800.0, -800.0})
        x.push_back(v);
    std::vector<double> sse2(x.size() + 8), avx2(x.size() + 8);
    using Kernel = void (*)(const double*, double*, std::size_t);
    const struct {
        const char* name;
        Kernel sse2, avx2;
    } kernels[] = {{"exp", detail::vector_exp_sse2, detail::vector_exp_avx2},
                   {"log", detail::vector_log_sse2, detail::vector_log_avx2}};
    for (const auto& k : kernels) {
        k.sse2(x.data(), sse2.data(), x.size());
        k.avx2(x.data(), avx2.data(), x.size());
        ASSERT_EQ(std::memcmp(sse2.data(), avx2.data(), x.size() * sizeof(double)), 0) << k.name;
        for (std::size_t offset = 0; offset < 4; ++offset)
            for (std::size_t length = 0; length < 12; ++length) {
                k.sse2(x.data() + offset + 299990, sse2.data() + offset, length);
                k.avx2(x.data() + offset + 299990, avx2.data() + offset, length);
                ASSERT_EQ(std::memcmp(sse2.data() + offset, avx2.data() + offset, length * sizeof(double)), 0)
                    << k.name << " at offset " << offset << ", length " << length;
            }
    }
}

} // namespace
} // namespace mhb
