// PMSM parameter identification from steady-state data (Li, Wang and Ji 2017, eq. 11): find
// theta = (Rs, Ld, Lq, psi) minimising the weighted squared mismatch between the measured dq
// voltages and the steady-state model (eq. 2) over paired samples of the id = 0 and the injected
// state. The data are fixed at construction. evaluate() is the hot loop of every PMSM study: by
// default it uses the constant-time expansion of eq. 11 about the least-squares optimum
// (expanded_fitness.hpp, ~30 flops); FitnessEvaluation::direct sums over the samples instead
// (no allocation either, ~16 flops per sample). Both are eq. 11; they agree to ~1e-13 relative.
//
// known_optimum() is the exact least-squares optimum when it lies inside the box; otherwise the
// exact box-constrained optimum (the best value an optimiser confined to the box can reach), so
// f - f* is never negative. least_squares() keeps both.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "problems/pmsm/dataset.hpp"
#include "problems/pmsm/expanded_fitness.hpp"
#include "problems/pmsm/least_squares.hpp"
#include "problems/pmsm/steady_state_data.hpp"
#include "problems/problem.hpp"

namespace mhb::pmsm {

// The paper's search box: Rs (0, 0.5), Ld (0, 0.01), Lq (0, 0.01), psi (0, 0.1).
Box paper_bounds();

enum class FitnessEvaluation { expanded, direct };

class SteadyStateProblem final : public Problem {
public:
    SteadyStateProblem(const Dataset& data, const FitnessWeights& weights, Box bounds,
                       FitnessEvaluation evaluation = FitnessEvaluation::expanded);
    // Samples already paired (several datasets: pair_samples), with the true values if known.
    SteadyStateProblem(SteadyStateData samples, std::optional<Eigen::Vector4d> truth, Box bounds,
                       FitnessEvaluation evaluation = FitnessEvaluation::expanded);

    std::string name() const override { return "pmsm"; }
    Eigen::Index dimension() const override { return 4; }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override;
    std::optional<KnownOptimum> known_optimum() const override;
    std::vector<std::string> parameter_names() const override { return {"Rs", "Ld", "Lq", "psi"}; }
    std::optional<Eigen::VectorXd> true_parameters() const override;
    std::vector<DataFile> data_files() const override { return files_; }
    // Says when the box-constrained optimum lies on a face of the box (the box, not the data,
    // then decides the answer).
    std::vector<std::string> warnings() const override;

    // Names the files the dataset was read from (the family does, for `data=`).
    void set_data_files(std::vector<DataFile> files) { files_ = std::move(files); }

    [[nodiscard]] const SteadyStateData& samples() const { return samples_; }
    [[nodiscard]] const LeastSquaresResult& least_squares() const { return least_squares_; }

private:
    SteadyStateData samples_;
    Box box_;
    LeastSquaresResult least_squares_;
    ExpandedFitness expanded_;
    bool direct_ = false;
    std::optional<Eigen::Vector4d> truth_;
    std::vector<DataFile> files_;
};

} // namespace mhb::pmsm
