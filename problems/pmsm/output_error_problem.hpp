// A PMSM identification problem on the output-error model (output_error.hpp): f(theta) is the
// squared mismatch between the measured currents and the currents simulated from the measured
// voltages and speed, over a search box. One evaluation is a simulation of every row, so
// parallel_evaluation() is true.
//
// The model is nonlinear, so unlike the linear problems there is no exact optimum to compare
// with. known_optimum() is a BEST KNOWN value: the lowest f that local refinement
// (refine_output_error, projected Levenberg-Marquardt) reached from the reference starts the
// caller gives (typically the dynamic least-squares estimate and the truth when known). It is not
// a proven global optimum: an optimiser may go below it (f - f* < 0), which then says the
// reference was a local minimum or not fully converged, not that the optimiser is wrong.
// warnings() says when that point lies on a face of the box (the box, not the motor, is found).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "problems/pmsm/output_error.hpp"
#include "problems/problem.hpp"

namespace mhb::pmsm {

class OutputErrorProblem final : public Problem {
public:
    // `truth`, when known, and every start have model.parameters() coordinates; starts are
    // clamped into the box before refinement. With no start (or none that can be simulated)
    // there is no known optimum. Throws std::invalid_argument on a bad box or a wrong size.
    OutputErrorProblem(OutputErrorModel model, Box bounds, std::optional<Eigen::VectorXd> truth,
                       const std::vector<Eigen::VectorXd>& reference_starts);

    std::string name() const override { return "pmsm"; }
    Eigen::Index dimension() const override { return model_.parameters(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override;
    std::optional<KnownOptimum> known_optimum() const override;
    std::vector<std::string> parameter_names() const override { return model_.parameter_names(); }
    std::optional<Eigen::VectorXd> true_parameters() const override { return truth_; }
    std::vector<DataFile> data_files() const override { return files_; }
    std::vector<std::string> warnings() const override;
    bool parallel_evaluation() const override { return true; }

    // Names the files the datasets were read from (the family does, for `data=`).
    void set_data_files(std::vector<DataFile> files) { files_ = std::move(files); }

    [[nodiscard]] const OutputErrorModel& model() const { return model_; }
    // The best refinement from the reference starts (f = +inf when there was none).
    [[nodiscard]] const Refinement& best_known() const { return best_; }

private:
    OutputErrorModel model_;
    Box box_;
    std::optional<Eigen::VectorXd> truth_;
    std::vector<DataFile> files_;
    Refinement best_;
};

} // namespace mhb::pmsm
