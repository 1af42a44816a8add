// What `mhbench identify` prints (runner/cli/identify_command.cpp computes it): the data, each
// estimate with its standard error (and its spread over seeds, its error when the truth is known),
// the fit's residuals and condition, a verdict per parameter, and what the numbers do not cover.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <ostream>
#include <string>

#include "problems/pmsm/identifiability.hpp"
#include "problems/pmsm/linear_model.hpp"
#include "problems/pmsm/output_error_identification.hpp"
#include "problems/pmsm/pmsm_sources.hpp"
#include "problems/problem.hpp"

namespace mhb::cli {

// The linear model whose fit gives estimates, standard errors and verdicts, and how it was made.
struct Identification {
    pmsm::LinearModel model;
    double volts_per_unit = 2.0; // the dynamic model's rows carry weight 0.25: half a volt per volt
    std::optional<pmsm::OutputIdentification> output;
    std::string title;
};

// What the printing steps share.
struct IdentifyReport {
    const Identification& id;
    const pmsm::LinearFit& fit;
    const Eigen::VectorXd& estimate;
    const std::optional<Eigen::VectorXd>& truth;
    pmsm::ModelKind kind;
    const char* unit; // of the equations' residuals
};

void print_data_summary(std::ostream& out, const pmsm::PmsmSources& data);
void print_estimates(std::ostream& out, const IdentifyReport& r);
void print_fit(std::ostream& out, const IdentifyReport& r);
void print_verdicts(std::ostream& out, const IdentifyReport& r, const pmsm::Identifiability& judged);
void print_caveats(std::ostream& out, const IdentifyReport& r, const Problem* problem,
                   const std::string& problem_spec);

} // namespace mhb::cli
