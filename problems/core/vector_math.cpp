// The kernels of vector_math.hpp. Each is one loop with no branch and no select over the common
// case (exp: |x| < 354, log: x positive, normal and finite), which GCC and clang vectorise without
// -ffast-math, and which also flags, in a few integer instructions, whether some input was not of
// it; those (infinities, NaN, zero, subnormals, exp's far range) are then redone one by one. A
// select in the main loop would cost four SSE2 instructions a double, and GCC (with its default
// -ftrapping-math) will not vectorise a loop whose multiplication it sees done on one path only.
// The main loops are compiled twice, for SSE2 and for AVX2 (taken where the processor has it), with
// the same bits (below).
//
// The polynomial coefficients are near-minimax fits by mpmath.chebyfit, rounded to double:
// scripts/vector-math-coefficients.py derives them and prints the approximation error (exp: 1.3e-17
// relative, log: 1.6e-18), far below the final roundings that make the 1 ulp.
#include "problems/core/vector_math.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "problems/core/matrix_vector.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define MHB_AVX2_KERNEL 1
#endif

namespace mhb {
namespace {

// Adding 1.5 * 2^52 to |v| < 2^51 rounds v to an integer (to nearest, ties to even), which then
// sits in the low bits of the sum; subtracting it again gives the integer as a double. SSE2 has no
// rounding instruction (SSE4.1's roundpd), nor a conversion of 64-bit integers to doubles.
constexpr double round_shift = 0x1.8p52;
constexpr std::uint64_t round_shift_bits = 0x4338000000000000;

// ln 2 = ln2_hi + ln2_lo, with ln2_hi of 32 significant bits, so that k ln2_hi is exact for the
// |k| < 2^21 used here (Cody and Waite's reduction).
constexpr double ln2_hi = 0x1.62e42feep-1;
constexpr double ln2_lo = 0x1.a39ef35793c76p-33;
constexpr double log2_e = 0x1.71547652b82fep0;

// 2^n for a double t = n + round_shift with -1022 <= n <= 1023: n + 1023 into the exponent field
// (the shift drops the high bits of round_shift_bits, whose low 12 bits are zero).
inline double power_of_two(double t) {
    return std::bit_cast<double>((std::bit_cast<std::uint64_t>(t) + 1023) << 52);
}

// exp(x) = 2^k exp(r), k = round(x / ln 2), |r| <= ln 2 / 2; exp(r) = 1 + r + r^2 q(r) with q of
// degree 9, summed last to first so that the error of r^2 q falls below 1's ulp. q by Estrin's
// scheme (pairs, then powers r^2 and r^4): half the chain of dependent operations of Horner's, which
// kept the processor waiting. Returns exp(r) and sets t = k + round_shift.
inline double exp_reduced(double x, double& t) {
    t = x * log2_e + round_shift;
    const double k = t - round_shift;
    const double r = (x - k * ln2_hi) - k * ln2_lo;
    const double r2 = r * r;
    const double r4 = r2 * r2;
    const double q01 = 0x1.0000000000001p-1 + 0x1.5555555555556p-3 * r;
    const double q23 = 0x1.5555555553d68p-5 + 0x1.11111111109b5p-7 * r;
    const double q45 = 0x1.6c16c17889ef1p-10 + 0x1.a01a01a7c2efep-13 * r;
    const double q67 = 0x1.a019b9149a41cp-16 + 0x1.71de0db2f6b19p-19 * r;
    const double q89 = 0x1.28917c89a43bcp-22 + 0x1.af389ecfc4bb6p-26 * r;
    const double q = (q01 + q23 * r2) + ((q45 + q67 * r2) + q89 * r4) * r4;
    return 1.0 + (r + r2 * q);
}

// exp beyond the main loop's range: x clamped to +-1080 (where the result is 0 or inf already;
// NaN passes), and 2^k applied in two halves, so that a subnormal result is rounded once and
// k = 1024 (a result just below the largest double) does not overflow on the way.
double exp_wide(double x) {
    x = x < -1080.0 ? -1080.0 : x;
    x = x > 1080.0 ? 1080.0 : x;
    double t = 0.0;
    const double u = exp_reduced(x, t);
    const double k = t - round_shift;
    const double t1 = k * 0.5 + round_shift;
    const double t2 = (k - (t1 - round_shift)) + round_shift;
    return u * power_of_two(t1) * power_of_two(t2);
}

// log(x) = k ln 2 + log(1 + f) for x = 2^k (1 + f), sqrt(1/2) <= 1 + f < sqrt(2): the offset
// moves sqrt(1/2)'s bits to 1's, so that the exponent field holds k + 1023 and the mantissa,
// given sqrt(1/2)'s exponent back, 1 + f. Then with s = f / (2 + f), log(1 + f) = 2 atanh s =
// 2s + s r, r = z p(z), z = s^2, p of degree 6 (Estrin), is summed as fdlibm's e_log.c does,
// f - (f^2/2 - s (f^2/2 + r)), so that the large terms are exact and the rounding errors fall on
// the small ones. x positive, normal, finite; the result is log(x) - scale ln 2 (for a subnormal
// scaled by 2^scale).
inline double log_normal(double x, double scale = 0.0) {
    constexpr std::uint64_t sqrt_half_bits = 0x3fe6a09e667f3bcd;
    const std::uint64_t u = std::bit_cast<std::uint64_t>(x) + (0x3ff0000000000000 - sqrt_half_bits);
    const double k = std::bit_cast<double>((u >> 52) + round_shift_bits) - (round_shift + 1023.0 + scale);
    const double f = std::bit_cast<double>((u & 0x000fffffffffffff) + sqrt_half_bits) - 1.0;
    const double s = f / (2.0 + f);
    const double z = s * s;
    const double z2 = z * z;
    const double p01 = 0x1.5555555555558p-1 + 0x1.99999999952e2p-2 * z;
    const double p23 = 0x1.2492492df148dp-2 + 0x1.c71c62e5800a1p-3 * z;
    const double p45 = 0x1.7462b4ab2ef6cp-3 + 0x1.39fe606542dbap-3 * z;
    const double p = (p01 + p23 * z2) + (p45 + 0x1.2b584aae78c14p-3 * z2) * (z2 * z2);
    const double r = z * p;
    const double half_f2 = 0.5 * f * f;
    return k * ln2_hi - ((half_f2 - (s * (half_f2 + r) + k * ln2_lo)) - f);
}

double log_special(double x) {
    if (x > 0.0 && x < std::numeric_limits<double>::min()) // subnormal: scaled into the normals
        return log_normal(x * 0x1p54, 54.0);
    if (x == 0.0)
        return -std::numeric_limits<double>::infinity();
    if (x < 0.0)
        return std::numeric_limits<double>::quiet_NaN();
    return x; // +inf, NaN
}

// The main loops: every element's value in y, right where x[i] is in the common case, and a
// nonzero result when some x[i] is not. Compiled twice below, for the baseline SSE2 and for AVX2.
//
// exp: the 2^k is right for -1022 <= k <= 1023; the loop flags k outside [-512, 511] (|x| about 355
// and beyond, inf, NaN), which t shows in three instructions: t + 512 has bits above the 10 low
// ones that t's own have not.
[[gnu::always_inline]] inline std::uint64_t exp_main(const double* x, double* y, std::size_t n) {
    std::uint64_t wide = 0;
    for (std::size_t i = 0; i < n; ++i) {
        double t = 0.0;
        const double u = exp_reduced(x[i], t);
        y[i] = u * power_of_two(t);
        wide |= ((std::bit_cast<std::uint64_t>(t) + 512) ^ round_shift_bits) >> 10;
    }
    return wide;
}

// log: flags x zero, subnormal, negative, inf or NaN (its exponent field with the sign, e, is 0 or
// at least 0x7ff).
[[gnu::always_inline]] inline std::uint64_t log_main(const double* x, double* y, std::size_t n) {
    std::uint64_t special = 0;
    for (std::size_t i = 0; i < n; ++i) {
        y[i] = log_normal(x[i]);
        const std::uint64_t e = std::bit_cast<std::uint64_t>(x[i]) >> 52;
        special |= ((e - 1) | (e + 1)) >> 11;
    }
    return special;
}

// Redone one by one: every element exp_main may have got wrong (|x| >= 354 includes all with
// |k| > 511), and a few it got right, to which exp_wide gives the same bits.
void exp_fix(const double* x, double* y, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        if (!(std::fabs(x[i]) < 354.0))
            y[i] = exp_wide(x[i]);
}

void log_fix(const double* x, double* y, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        if (!(x[i] >= std::numeric_limits<double>::min() && x[i] <= std::numeric_limits<double>::max()))
            y[i] = log_special(x[i]);
}

#ifdef MHB_AVX2_KERNEL
// The same loops in four-double registers. Each element gets the same IEEE operations in the same
// order as in the SSE2 loop, and AVX2 without FMA has no fused multiply-add to contract them into,
// so the values are the same bits (tests/unit/problems/vector_math_test.cpp compares them).
__attribute__((target("avx2"))) std::uint64_t exp_main_avx2(const double* x, double* y, std::size_t n) {
    return exp_main(x, y, n);
}
__attribute__((target("avx2"))) std::uint64_t log_main_avx2(const double* x, double* y, std::size_t n) {
    return log_main(x, y, n);
}
#endif

} // namespace

namespace detail {

void vector_exp_sse2(const double* x, double* y, std::size_t n) {
    if (exp_main(x, y, n) != 0)
        exp_fix(x, y, n);
}

void vector_log_sse2(const double* x, double* y, std::size_t n) {
    if (log_main(x, y, n) != 0)
        log_fix(x, y, n);
}

#ifdef MHB_AVX2_KERNEL

void vector_exp_avx2(const double* x, double* y, std::size_t n) {
    if (exp_main_avx2(x, y, n) != 0)
        exp_fix(x, y, n);
}

void vector_log_avx2(const double* x, double* y, std::size_t n) {
    if (log_main_avx2(x, y, n) != 0)
        log_fix(x, y, n);
}

#else

void vector_exp_avx2(const double* x, double* y, std::size_t n) {
    vector_exp_sse2(x, y, n);
}

void vector_log_avx2(const double* x, double* y, std::size_t n) {
    vector_log_sse2(x, y, n);
}

#endif

} // namespace detail

void vector_exp(const double* x, double* y, std::size_t n) {
    if (detail::processor_has_avx2())
        detail::vector_exp_avx2(x, y, n);
    else
        detail::vector_exp_sse2(x, y, n);
}

void vector_log(const double* x, double* y, std::size_t n) {
    if (detail::processor_has_avx2())
        detail::vector_log_avx2(x, y, n);
    else
        detail::vector_log_sse2(x, y, n);
}

} // namespace mhb
