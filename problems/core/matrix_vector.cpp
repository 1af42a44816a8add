#include "problems/core/matrix_vector.hpp"

#include <cstddef>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define MHB_AVX2_KERNEL 1
#include <immintrin.h>
#endif

namespace mhb {

namespace detail {

void multiply_square_eigen(const Eigen::MatrixXd& m, const double* in, double* out) {
    const Eigen::Index n = m.rows();
    Eigen::Map<Eigen::VectorXd>(out, n).noalias() = m * Eigen::Map<const Eigen::VectorXd>(in, n);
}

#ifdef MHB_AVX2_KERNEL

namespace {

// Rows [row, row + 4 Registers) of m in: each register holds four out_i and adds m_ij in_j for
// j = 0, 1, ... in turn, from zero, as Eigen does. The final + 0 is Eigen's too (it adds the sum
// to the zeroed destination), and turns a sum of -0 into +0 as there.
template <std::size_t Registers>
__attribute__((target("avx2"))) inline void block_rows(const double* m, Eigen::Index n, Eigen::Index row,
                                                       const double* in, double* out) {
    const __m256d zero = _mm256_setzero_pd();
    __m256d sum[Registers];
    for (std::size_t k = 0; k < Registers; ++k)
        sum[k] = zero;
    const double* column = m + row;
    for (Eigen::Index j = 0; j < n; ++j, column += n) {
        const __m256d x = _mm256_broadcast_sd(in + j);
        for (std::size_t k = 0; k < Registers; ++k)
            sum[k] = _mm256_add_pd(sum[k], _mm256_mul_pd(_mm256_loadu_pd(column + 4 * k), x));
    }
    for (std::size_t k = 0; k < Registers; ++k)
        _mm256_storeu_pd(out + row + 4 * k, _mm256_add_pd(sum[k], zero));
}

} // namespace

__attribute__((target("avx2"))) void multiply_square_avx2(const Eigen::MatrixXd& m, const double* in,
                                                          double* out) {
    const Eigen::Index n = m.rows();
    const double* data = m.data();
    Eigen::Index row = 0;
    for (; row + 16 <= n; row += 16)
        block_rows<4>(data, n, row, in, out);
    for (; row + 4 <= n; row += 4)
        block_rows<1>(data, n, row, in, out);
    for (; row < n; ++row) {
        double sum = 0.0;
        for (Eigen::Index j = 0; j < n; ++j)
            sum += data[j * n + row] * in[j];
        out[row] = sum + 0.0;
    }
}

bool processor_has_avx2() {
    static const bool avx2 = __builtin_cpu_supports("avx2"); // asked once per process
    return avx2;
}

#else

void multiply_square_avx2(const Eigen::MatrixXd& m, const double* in, double* out) {
    multiply_square_eigen(m, in, out);
}

bool processor_has_avx2() {
    return false;
}

#endif

} // namespace detail

void multiply_square(const Eigen::MatrixXd& m, const double* in, double* out) {
    if (detail::processor_has_avx2() && m.rows() < detail::eigen_one_block_limit)
        detail::multiply_square_avx2(m, in, out);
    else
        detail::multiply_square_eigen(m, in, out);
}

} // namespace mhb
