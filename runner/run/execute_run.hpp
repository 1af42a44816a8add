// One run: an optimiser on a problem with its own random stream, turned into a RunRecord.
// This is the single place where a run's stream is derived and its record filled, so the
// parallel runner, the tests and the benchmarks all produce identical records.
#pragma once

#include <cstdint>
#include <string>

#include "algorithms/optimizer.hpp"
#include "problems/objective.hpp"
#include "problems/problem.hpp"
#include "results/store/run_record.hpp"

namespace mhb {

struct RunRequest {
    const Optimizer* optimizer = nullptr;
    const Problem* problem = nullptr;
    std::string algorithm_spec; // canonical
    std::string problem_spec;   // canonical
    std::int64_t run_id = 0;
    std::int64_t run_index = 0;
    std::uint64_t seed = 0; // the run's stream (derived by the study from its seed mode)
    Budget budget;
    std::string budget_text; // budget_text(budget), kept in the record
};

// Runs the request. A run that throws (other than by spending its budget) becomes a failed
// record carrying the message; this function itself does not throw for it.
RunRecord execute_run(const RunRequest& request);

} // namespace mhb
