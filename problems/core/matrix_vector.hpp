// out = M in for a square column-major matrix: Eigen's matrix-vector product, bit for bit, with a
// kernel of four-double (AVX2) registers where the processor has them.
//
// Why it is exact: below 128 columns, Eigen 3.4's column-major product sums each out_i over j in
// order, starting from zero, at every vector width (from 128 on it sums blocks of columns and
// adds the blocks' sums, and Eigen's product is used; tests/unit/problems/matrix_vector_test.cpp
// checks both sides of that line). The AVX2 kernel keeps that order and multiplies and adds
// separately (no fused multiply-add, which would round once instead of twice), so a run's
// records are the same with either kernel, on any x86-64 processor. The rotations of the CEC
// functions are most of their time at D = 50 and 100 (BENCHMARKS.md).
#pragma once

#include <Eigen/Core>

namespace mhb {

// out = m in; m square (n x n, n = m.rows()), in and out n doubles each, not overlapping.
void multiply_square(const Eigen::MatrixXd& m, const double* in, double* out);

namespace detail {
// The two kernels, for the test that compares them, and whether this processor runs the AVX2 one
// (asked once per process).
void multiply_square_eigen(const Eigen::MatrixXd& m, const double* in, double* out);
void multiply_square_avx2(const Eigen::MatrixXd& m, const double* in, double* out);
bool processor_has_avx2();
// Eigen sums all columns in one block below this many (GeneralMatrixVector.h, block_cols).
inline constexpr Eigen::Index eigen_one_block_limit = 128;
} // namespace detail

} // namespace mhb
