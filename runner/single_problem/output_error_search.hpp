// The search of `mhbench identify --model output`: a chosen optimiser (by default CMA-ES with
// IPOP restarts) run from several seeds in parallel on the output-error problem, each run through
// execute_run as a study's run is. What the seeds' best points mean (the estimate, their spread,
// the linearised standard errors) is the PMSM's and lives beside its models
// (problems/pmsm/output_error_identification.hpp); only the part that needs an optimiser from
// algorithms/ stays here, since problems/ may not depend on algorithms/ or runner/.
#pragma once

#include <cstdint>
#include <string>

#include "problems/pmsm/output_error_identification.hpp"
#include "problems/pmsm/output_error_problem.hpp"

namespace mhb {

struct OutputIdentificationOptions {
    std::string algorithm = "cmaes"; // a spec of the algorithm registry
    int seeds = 8;
    std::int64_t evaluations = 20000; // per seed
    std::uint64_t seed = 1;
    int threads = 0; // 0: all cores
};

// Throws std::invalid_argument for an unknown algorithm, std::runtime_error if every seed fails.
pmsm::OutputIdentification identify_output_error(const pmsm::OutputErrorProblem& problem,
                                                 const OutputIdentificationOptions& options);

} // namespace mhb
