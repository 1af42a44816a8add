#include "algorithms/symmetric_eigensolver.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Jacobi>
#include <cmath>
#include <limits>
#include <utility>

#include "problems/core/matrix_vector.hpp" // detail::processor_has_avx2

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define MHB_AVX2_ROTATION 1
#include <immintrin.h>
#endif

namespace mhb {

namespace detail {

void rotate_columns_portable(double* x, double* y, Eigen::Index n, double c, double s) {
    for (Eigen::Index i = 0; i < n; ++i) {
        const double xi = x[i];
        const double yi = y[i];
        x[i] = c * xi + s * yi;
        y[i] = c * yi - s * xi;
    }
}

#ifdef MHB_AVX2_ROTATION
// Multiplications and additions apart (no FMA): the roundings of the portable loop and of Eigen.
__attribute__((target("avx2"))) void rotate_columns_avx2(double* x, double* y, Eigen::Index n, double c,
                                                         double s) {
    const __m256d pc = _mm256_set1_pd(c);
    const __m256d ps = _mm256_set1_pd(s);
    Eigen::Index i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m256d xi = _mm256_loadu_pd(x + i);
        const __m256d yi = _mm256_loadu_pd(y + i);
        _mm256_storeu_pd(x + i, _mm256_add_pd(_mm256_mul_pd(pc, xi), _mm256_mul_pd(ps, yi)));
        _mm256_storeu_pd(y + i, _mm256_sub_pd(_mm256_mul_pd(pc, yi), _mm256_mul_pd(ps, xi)));
    }
    rotate_columns_portable(x + i, y + i, n - i, c, s);
}
#else
void rotate_columns_avx2(double* x, double* y, Eigen::Index n, double c, double s) {
    rotate_columns_portable(x, y, n, c, s);
}
#endif

} // namespace detail

namespace {

void rotate_columns(double* x, double* y, Eigen::Index n, double c, double s) {
    if (detail::processor_has_avx2())
        detail::rotate_columns_avx2(x, y, n, c, s);
    else
        detail::rotate_columns_portable(x, y, n, c, s);
}

} // namespace

void SymmetricEigensolver::compute(const Eigen::MatrixXd& matrix) {
    const Eigen::Index n = matrix.cols();
    values_.resize(n);
    if (n == 1) {
        values_[0] = matrix(0, 0);
        vectors_.setOnes(1, 1);
        converged_ = true;
        return;
    }
    // Scaled into [-1, 1] against over- and underflow; the lower triangle only.
    vectors_ = matrix.triangularView<Eigen::Lower>();
    double scale = vectors_.cwiseAbs().maxCoeff();
    if (scale == 0.0)
        scale = 1.0;
    vectors_.triangularView<Eigen::Lower>() /= scale;
    subdiagonal_.resize(n - 1);
    householder_.resize(n - 1);
    // Eigen's own tridiagonalisation, which also forms Q in place (SelfAdjointEigenSolver calls
    // the same internal routine; the public Tridiagonalization forms Q by another path).
    Eigen::internal::tridiagonalization_inplace(vectors_, values_, subdiagonal_, householder_, true);

    converged_ = iterate();
    if (converged_)
        sort_ascending();
    values_ *= scale;
}

// The implicit QR iteration of Eigen's computeFromTridiagonal_impl: deflate the negligible
// subdiagonal entries, take the largest unreduced block at the end, one step on it; false when
// it gave up after 30 n steps.
bool SymmetricEigensolver::iterate() {
    const Eigen::Index n = values_.size();
    const double consider_as_zero = std::numeric_limits<double>::min();
    const double precision_inverse = 1.0 / std::numeric_limits<double>::epsilon();
    const Eigen::Index max_iterations = 30 * n; // Eigen's m_maxIterations (30) times n
    Eigen::Index end = n - 1;
    Eigen::Index start = 0;
    Eigen::Index iterations = 0;
    while (end > 0) {
        for (Eigen::Index i = start; i < end; ++i) {
            if (std::abs(subdiagonal_[i]) < consider_as_zero) {
                subdiagonal_[i] = 0.0;
            } else {
                const double scaled = precision_inverse * subdiagonal_[i];
                if (scaled * scaled <= std::abs(values_[i]) + std::abs(values_[i + 1]))
                    subdiagonal_[i] = 0.0;
            }
        }
        while (end > 0 && subdiagonal_[end - 1] == 0.0)
            --end;
        if (end <= 0)
            break;
        if (++iterations > max_iterations)
            break;
        start = end - 1;
        while (start > 0 && subdiagonal_[start - 1] != 0.0)
            --start;
        qr_step(start, end);
    }
    return iterations <= max_iterations;
}

// As Eigen sorts: for each position, the smallest of the rest swapped into it with its vector.
void SymmetricEigensolver::sort_ascending() {
    const Eigen::Index n = values_.size();
    for (Eigen::Index i = 0; i < n - 1; ++i) {
        Eigen::Index k = 0;
        values_.segment(i, n - i).minCoeff(&k);
        if (k > 0) {
            std::swap(values_[i], values_[k + i]);
            vectors_.col(i).swap(vectors_.col(k + i));
        }
    }
}

// Eigen's tridiagonal_qr_step: a Wilkinson shift, then the bulge chased down [start, end], each
// Givens rotation applied to the eigenvectors as soon as it is made.
void SymmetricEigensolver::qr_step(Eigen::Index start, Eigen::Index end) {
    double* diag = values_.data();
    double* subdiag = subdiagonal_.data();
    const double td = (diag[end - 1] - diag[end]) * 0.5;
    const double e = subdiag[end - 1];
    double mu = diag[end];
    if (td == 0.0) {
        mu -= std::abs(e);
    } else if (e != 0.0) {
        const double e2 = e * e;
        const double h = Eigen::numext::hypot(td, e);
        if (e2 == 0.0)
            mu -= e / ((td + (td > 0.0 ? h : -h)) / e);
        else
            mu -= e2 / (td + (td > 0.0 ? h : -h));
    }
    double x = diag[start] - mu;
    double z = subdiag[start];
    const Eigen::Index n = vectors_.rows();
    for (Eigen::Index k = start; k < end && z != 0.0; ++k) {
        Eigen::JacobiRotation<double> rotation;
        rotation.makeGivens(x, z);
        const double c = rotation.c();
        const double s = rotation.s();
        const double sdk = s * diag[k] + c * subdiag[k];
        const double dkp1 = s * subdiag[k] + c * diag[k + 1];
        diag[k] = c * (c * diag[k] - s * subdiag[k]) - s * (c * subdiag[k] - s * diag[k + 1]);
        diag[k + 1] = s * sdk + c * dkp1;
        subdiag[k] = c * sdk - s * dkp1;
        if (k > start)
            subdiag[k - 1] = c * subdiag[k - 1] - s * z;
        x = subdiag[k];
        if (k < end - 1) {
            z = -s * subdiag[k + 1];
            subdiag[k + 1] = c * subdiag[k + 1];
        }
        // Q = Q G: Eigen applies the transposed rotation (c, -s) to columns k, k + 1, and skips
        // the identity.
        if (!(c == 1.0 && s == 0.0))
            rotate_columns(vectors_.col(k).data(), vectors_.col(k + 1).data(), n, c, -s);
    }
}

} // namespace mhb
