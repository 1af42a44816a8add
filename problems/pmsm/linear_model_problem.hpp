// A PMSM identification problem whose model is linear in the parameters (the dynamic model;
// see dynamic_model.hpp): f(theta) = |b - A theta|^2 over a search box. evaluate() costs O(k^2)
// whatever the number of samples, by the expansion about the least-squares optimum (as
// expanded_fitness.hpp does for eq. 11, for k = 4 or 5 parameters), and allocates nothing.
//
// known_optimum() is the exact least-squares optimum when it lies in the box, else the exact
// box-constrained optimum, so f - f* is never negative; warnings() says when it lies on a face
// of the box (an optimiser then finds the box, not the motor).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "problems/pmsm/linear_model.hpp"
#include "problems/problem.hpp"

namespace mhb::pmsm {

class LinearModelProblem final : public Problem {
public:
    // `truth`, when known, has the model's k parameters. Throws std::invalid_argument when the
    // box has not k coordinates or the data leave a parameter undetermined (rank < k), naming it.
    LinearModelProblem(LinearModel model, Box bounds, std::optional<Eigen::VectorXd> truth);

    std::string name() const override { return "pmsm"; }
    Eigen::Index dimension() const override { return model_.parameters(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override;
    std::optional<KnownOptimum> known_optimum() const override;
    std::vector<std::string> parameter_names() const override { return model_.parameter_names; }
    std::optional<Eigen::VectorXd> true_parameters() const override { return truth_; }
    std::vector<DataFile> data_files() const override { return files_; }
    std::vector<std::string> warnings() const override;

    void set_data_files(std::vector<DataFile> files) { files_ = std::move(files); }
    [[nodiscard]] const LinearModel& model() const { return model_; }
    [[nodiscard]] const LinearFit& fit() const { return fit_; }

private:
    LinearModel model_;
    Box box_;
    LinearFit fit_;
    std::optional<Eigen::VectorXd> truth_;
    std::vector<DataFile> files_;
    // The expansion f(theta) = f0 + 2 g0.d + |R d|^2, d = theta - theta0 (k <= 5).
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 5, 1> theta0_, g0_;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 5, 5> r_;
    double f0_ = 0.0;
};

} // namespace mhb::pmsm
