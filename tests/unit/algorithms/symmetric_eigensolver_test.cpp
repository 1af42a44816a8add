// SymmetricEigensolver is Eigen's SelfAdjointEigenSolver bit for bit (eigenvalues and eigenvectors)
// on covariance-like, indefinite, diagonal and rank-deficient matrices of every size to 40 and at
// 50 and 100, whichever rotation kernel this processor runs; and the two kernels agree.
#include <Eigen/Eigenvalues>
#include <cstring>
#include <gtest/gtest.h>
#include <string>

#include "algorithms/symmetric_eigensolver.hpp"
#include "problems/core/matrix_vector.hpp"
#include "problems/core/rng.hpp"

namespace mhb {
namespace {

bool same_bits(const double* a, const double* b, Eigen::Index n) {
    return std::memcmp(a, b, static_cast<std::size_t>(n) * sizeof(double)) == 0;
}

Eigen::MatrixXd random_matrix(Eigen::Index n, Rng& rng) {
    Eigen::MatrixXd a(n, n);
    for (Eigen::Index i = 0; i < a.size(); ++i)
        a.data()[i] = rng.normal();
    return a;
}

void expect_as_eigen(const Eigen::MatrixXd& m, const std::string& what) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(m);
    SymmetricEigensolver ours;
    ours.compute(m);
    ASSERT_EQ(ours.converged(), eigen.info() == Eigen::Success) << what;
    ASSERT_TRUE(same_bits(ours.eigenvalues().data(), eigen.eigenvalues().data(), m.rows())) << what;
    ASSERT_TRUE(same_bits(ours.eigenvectors().data(), eigen.eigenvectors().data(), m.size())) << what;
}

TEST(SymmetricEigensolver, IsEigensSolverBitForBit) {
    Rng rng(100);
    for (Eigen::Index n = 1; n <= 40; ++n) {
        const Eigen::MatrixXd a = random_matrix(n, rng);
        const Eigen::MatrixXd covariance =
            a * a.transpose() / static_cast<double>(n) + Eigen::MatrixXd::Identity(n, n);
        expect_as_eigen(covariance, "covariance, n = " + std::to_string(n));
        expect_as_eigen(a + a.transpose(), "indefinite, n = " + std::to_string(n));
    }
    for (const Eigen::Index n : {50, 100}) {
        const Eigen::MatrixXd a = random_matrix(n, rng);
        expect_as_eigen(a * a.transpose(), "covariance, n = " + std::to_string(n));
        // A CMA-ES covariance late in a run: condition number 1e10.
        Eigen::VectorXd scales(n);
        for (Eigen::Index i = 0; i < n; ++i)
            scales[i] = std::pow(1e10, static_cast<double>(i) / static_cast<double>(n - 1));
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
        const Eigen::MatrixXd q = qr.householderQ();
        expect_as_eigen(q * scales.asDiagonal() * q.transpose(), "ill-conditioned, n = " + std::to_string(n));
    }
    expect_as_eigen(Eigen::VectorXd::LinSpaced(7, 3.0, -3.0).asDiagonal(), "diagonal");
    const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(9, -1.0, 1.0);
    expect_as_eigen(v * v.transpose(), "rank one");
    expect_as_eigen(Eigen::MatrixXd::Zero(5, 5), "zero");
}

TEST(SymmetricEigensolver, TheRotationKernelsAgree) {
    if (!detail::processor_has_avx2())
        GTEST_SKIP() << "this processor has no AVX2";
    Rng rng(3);
    for (Eigen::Index n = 1; n <= 37; ++n) {
        Eigen::VectorXd x1(n), y1(n);
        for (Eigen::Index i = 0; i < n; ++i) {
            x1[i] = i % 5 == 0 ? -0.0 : rng.normal();
            y1[i] = i % 7 == 0 ? 0.0 : rng.normal();
        }
        Eigen::VectorXd x2 = x1, y2 = y1;
        const double angle = rng.uniform(-3.0, 3.0);
        detail::rotate_columns_portable(x1.data(), y1.data(), n, std::cos(angle), std::sin(angle));
        detail::rotate_columns_avx2(x2.data(), y2.data(), n, std::cos(angle), std::sin(angle));
        ASSERT_TRUE(same_bits(x1.data(), x2.data(), n) && same_bits(y1.data(), y2.data(), n)) << "n = " << n;
    }
}

} // namespace
} // namespace mhb
