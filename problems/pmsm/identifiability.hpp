// What a dataset determines: a plain verdict per identified parameter (determined / poorly
// determined / not identifiable from this data) with what to change in the experiment, and the
// size of each parameter's signal in the data, computed from the fit of a linear model (the
// steady and dynamic models, or the output-error model linearised at its estimate).
//
// The rules, from the relative standard error s = SE / |estimate| and the participation of the
// parameter in the weakest direction of the scaled design (|v_min| of its column, the last right
// singular vector of A with unit-norm columns) at a scaled condition number kappa:
//   not identifiable  the data leave it undetermined (rank), or s > 50 %, or kappa > 1e8 and
//                     |v_min| > 0.1 (nearly collinear: a tiny change of the data swaps it with
//                     another parameter however small the noise);
//   poorly determined s > 5 %, or kappa > 1e5 and |v_min| > 0.1;
//   determined        otherwise.
// The advice names the signal that carries the parameter in the chosen model and how to make it
// larger; "a longer window" is added when there are fewer than 25 equations per parameter.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "problems/pmsm/linear_model.hpp"

namespace mhb::pmsm {

enum class ModelKind { steady, dynamic, output };
const char* to_string(ModelKind kind);

enum class Verdict { determined, poorly_determined, not_identifiable };
const char* to_string(Verdict verdict);

struct ParameterJudgement {
    std::string name;
    Verdict verdict = Verdict::determined;
    double relative_error = 0.0; // SE / |estimate|; inf when undetermined, NaN without residual
    double weak_direction = 0.0; // |v_min| of the parameter in the scaled design
    double signal_rms = 0.0;     // RMS over the equations of the parameter's term (column x estimate)
    std::string reason;          // why this verdict, from the numbers
    std::string advice;          // what to change; empty when determined
};

struct Identifiability {
    std::vector<ParameterJudgement> parameters;
    double condition_number = 0.0;
    std::vector<std::string> notes; // about the whole fit: residual correlation, window length
};

Identifiability judge_identifiability(const LinearModel& model, const LinearFit& fit, ModelKind kind);

} // namespace mhb::pmsm
