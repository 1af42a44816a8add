// exp and log over arrays of doubles, within 1 ulp, and the same bits on every x86-64 processor
// for a given build.
//
// Why our own: Eigen's SSE2 exp and log (about 6 ns a double on the project's machine, much of it
// emulating SSE4.1's rounding, and a division) were most of a flux-map evaluation. These are plain
// loops of IEEE additions and multiplications (no table, no library call) that GCC and clang
// vectorise: with the baseline SSE2, 2.7 ns an exp and 3.7 a log; compiled a second time for AVX2,
// taken where the processor has it, 1.3 and 1.6. The two give each element the same IEEE
// operations in the same order and AVX2 has no fused multiply-add to contract them into, so a value
// does not depend on the processor (the test compares them bit for bit); a build with -march=native
// may fuse them, and is another build.
//
// Accuracy, measured against glibc's std::exp and std::log by tests/unit/problems/
// vector_math_test.cpp: at most 1 ulp apart over all doubles, subnormal results and arguments
// included. Special values as std::: exp(-inf) = 0, exp(+inf) = +inf, exp(x) = 0 below about
// -745.13 and +inf above about 709.78 (so an overflow reaches an objective as inf, not NaN);
// log(0) = -inf, log(+inf) = +inf, log(x < 0) = NaN; NaN in, NaN out.
#pragma once

#include <cstddef>

namespace mhb {

// y[i] = exp(x[i]) for i < n; x and y must not overlap.
void vector_exp(const double* x, double* y, std::size_t n);
// y[i] = log(x[i]) for i < n; x and y must not overlap.
void vector_log(const double* x, double* y, std::size_t n);

namespace detail {
// The kernels with their loops in SSE2 and in AVX2 registers (the latter on a processor with AVX2
// only), for the test that compares them bit for bit; vector_exp and vector_log take the AVX2 ones
// where detail::processor_has_avx2() (problems/core/matrix_vector.hpp).
void vector_exp_sse2(const double* x, double* y, std::size_t n);
void vector_exp_avx2(const double* x, double* y, std::size_t n);
void vector_log_sse2(const double* x, double* y, std::size_t n);
void vector_log_avx2(const double* x, double* y, std::size_t n);
} // namespace detail

} // namespace mhb
