// The eigendecomposition of a symmetric matrix as Eigen 3.4's SelfAdjointEigenSolver computes it,
// bit for bit (tests/unit/algorithms/symmetric_eigensolver_test.cpp compares the two): the same
// scaling, Householder tridiagonalisation (Eigen's own routine) and implicit symmetric QR steps
// with Wilkinson's shift, eigenvalues ascending with their vectors. What is ours is applying each
// step's Givens rotations to the eigenvectors, half of the solver's time at D = 100 (BENCHMARKS.md):
// an AVX2 kernel where the processor has one, with the same products and sums, element by element,
// as Eigen's. CMA-ES decomposes its covariance with it.
#pragma once

#include <Eigen/Core>

namespace mhb {

class SymmetricEigensolver {
public:
    // Decomposes `matrix` (square; only its lower triangle is read, as Eigen does).
    void compute(const Eigen::MatrixXd& matrix);

    // Ascending; unsorted if the QR iteration did not converge (as Eigen leaves them).
    [[nodiscard]] const Eigen::VectorXd& eigenvalues() const { return values_; }
    // Column i belongs to eigenvalue i.
    [[nodiscard]] const Eigen::MatrixXd& eigenvectors() const { return vectors_; }
    // False when the QR iteration gave up after 30 n steps (Eigen's NoConvergence).
    [[nodiscard]] bool converged() const { return converged_; }

private:
    bool iterate();
    void qr_step(Eigen::Index start, Eigen::Index end);
    void sort_ascending();

    Eigen::MatrixXd vectors_;
    Eigen::VectorXd values_;
    Eigen::VectorXd subdiagonal_;
    Eigen::VectorXd householder_;
    bool converged_ = false;
};

namespace detail {
// Columns x, y of n doubles: x <- c x + s y, y <- c y - s x, element by element, as Eigen applies
// a rotation on the right (JacobiRotation::transpose of makeGivens's). Two kernels, for the test.
void rotate_columns_portable(double* x, double* y, Eigen::Index n, double c, double s);
void rotate_columns_avx2(double* x, double* y, Eigen::Index n, double c, double s);
} // namespace detail

} // namespace mhb
