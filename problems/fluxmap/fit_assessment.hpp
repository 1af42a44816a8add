// What a least-squares fit of a current map to a flux map determines, for `mhbench identify
// --flux-map`: each parameter's standard error, its strongest correlation, how far the starts that
// reached the best value spread, and a verdict with its reason; the current errors of the fit.
//
// Standard errors: the Jacobian J of the residuals (A) by central differences at the estimate,
// covariance s^2 (J'J)^-1 over the free parameters with s^2 = f / (2 n - p_free) (n points, two
// residuals each). A parameter on its bound is not free: the box, not the data, fixes it.
//
// Verdicts, from the relative standard error r = SE / |estimate|, the parameter's share |v| of the
// weakest direction of the design with unit-norm columns (last right singular vector) and that
// design's condition number kappa (the rules of the PMSM `identify`, problems/pmsm/identifiability.hpp):
//   not determined     on a bound, or r > 50 %, or kappa > 1e8 and |v| > 0.1;
//   weakly determined  r > 5 %, or kappa > 1e5 and |v| > 0.1;
//   well determined    otherwise.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "problems/fluxmap/current_map.hpp"
#include "problems/problem.hpp"

namespace mhb::fluxmap {

enum class Determination { well, weakly, not_determined };
const char* to_string(Determination determination);

struct ParameterAssessment {
    std::string name;
    double estimate = 0.0;
    double standard_error = 0.0; // NaN on a bound
    double relative_error = 0.0; // SE / |estimate|
    bool on_bound = false;
    std::string partner;      // the free parameter it correlates with most (empty if none)
    double correlation = 0.0; // with the partner
    double spread = 0.0;      // max |theta_j - estimate_j| over the starts that reached f
    Determination verdict = Determination::well;
    std::string reason; // the numbers behind the verdict, in words
};

// Current errors of the fit over the map's points, A: e_k = (i_d,model - i_d, i_q,model - i_q).
struct CurrentErrors {
    double rms_d = 0.0, rms_q = 0.0;    // per axis
    double rms = 0.0;                   // sqrt(mean |e_k|^2) = sqrt(f / n)
    double worst = 0.0;                 // max |e_k|
    Eigen::Index worst_point = 0;       // its index in the map
    double neighbour_correlation = 0.0; // of consecutive points' residuals in the file's order
};

struct FitAssessment {
    std::vector<ParameterAssessment> parameters;
    double f = 0.0;                   // A^2
    Eigen::Index free_parameters = 0; // not on a bound
    double residual_sigma = 0.0;      // s, A
    double condition_number = 0.0;    // of the free columns scaled to unit norm
    CurrentErrors errors;
};

CurrentErrors current_errors(const CurrentMap& map, const Eigen::VectorXd& theta);

// `reached`: the end points of the starts that reached f (the best among them is theta).
FitAssessment assess_fit(const CurrentMap& map, const Box& box, const Eigen::VectorXd& theta,
                         const std::vector<Eigen::VectorXd>& reached);

} // namespace mhb::fluxmap
