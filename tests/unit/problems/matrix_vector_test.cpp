// multiply_square: the AVX2 kernel equals Eigen's matrix-vector product bit for bit, at every size
// the test functions use and beyond, on inputs with zeros of both signs and at any alignment, so
// that records do not depend on the processor a run had.
#include <bit>
#include <cstdint>
#include <gtest/gtest.h>
#include <vector>

#include "problems/core/matrix_vector.hpp"
#include "problems/core/rng.hpp"

namespace mhb {
namespace {

// 0 when the two vectors are equal bit for bit (so +0 and -0 differ), else the first index + 1.
std::size_t first_bit_difference(const double* a, const double* b, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i]))
            return i + 1;
    return 0;
}

TEST(MatrixVector, TheAvx2KernelEqualsEigenBitForBit) {
    if (!detail::processor_has_avx2())
        GTEST_SKIP() << "this processor has no AVX2; multiply_square uses Eigen's product";
    Rng rng(2017);
    for (Eigen::Index n = 1; n < detail::eigen_one_block_limit; ++n) {
        Eigen::MatrixXd m(n, n);
        for (Eigen::Index i = 0; i < m.size(); ++i)
            m.data()[i] = rng.normal();
        std::vector<double> storage(static_cast<std::size_t>(n) + 3);
        std::vector<double> eigen(static_cast<std::size_t>(n) + 1), avx2(static_cast<std::size_t>(n) + 1);
        for (int trial = 0; trial < 20; ++trial) {
            double* in = storage.data() + trial % 3; // aligned and not
            for (Eigen::Index j = 0; j < n; ++j) {
                const double u = rng.uniform();
                in[j] = u < 0.1 ? 0.0 : u < 0.2 ? -0.0 : 100.0 * rng.normal();
            }
            if (trial == 0) // a zero row of m: its sum of zero products must be +0 as Eigen's
                m.row(0).setZero();
            double* out_eigen = eigen.data() + trial % 2;
            double* out_avx2 = avx2.data() + (trial + 1) % 2;
            detail::multiply_square_eigen(m, in, out_eigen);
            detail::multiply_square_avx2(m, in, out_avx2);
            ASSERT_EQ(first_bit_difference(out_eigen, out_avx2, static_cast<std::size_t>(n)), 0u)
                << "n = " << n << ", trial " << trial;
        }
    }
}

TEST(MatrixVector, FromEigensBlockLimitOnItIsEigensProduct) {
    Rng rng(7);
    for (const Eigen::Index n : {detail::eigen_one_block_limit, detail::eigen_one_block_limit + 3}) {
        Eigen::MatrixXd m(n, n);
        for (Eigen::Index i = 0; i < m.size(); ++i)
            m.data()[i] = rng.normal();
        std::vector<double> in(static_cast<std::size_t>(n)), eigen(in.size()), used(in.size());
        for (double& x : in)
            x = 100.0 * rng.normal();
        detail::multiply_square_eigen(m, in.data(), eigen.data());
        multiply_square(m, in.data(), used.data());
        EXPECT_EQ(first_bit_difference(eigen.data(), used.data(), in.size()), 0u) << "n = " << n;
    }
}

TEST(MatrixVector, MultiplySquareIsTheProduct) {
    Eigen::MatrixXd m(3, 3);
    m << 1, 2, 3, 4, 5, 6, 7, 8, 10;
    const double in[3] = {1, -1, 2};
    double out[3] = {};
    multiply_square(m, in, out);
    EXPECT_EQ(out[0], 1 - 2 + 6);
    EXPECT_EQ(out[1], 4 - 5 + 12);
    EXPECT_EQ(out[2], 7 - 8 + 20);
}

} // namespace
} // namespace mhb
