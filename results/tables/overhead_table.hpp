// The "overhead" table: per problem and algorithm, the median wall time per evaluation in
// microseconds over the runs (results/analysis/evaluation_time.hpp), COCO's timing experiment when
// the problems are the sphere at growing dimension (scripts/studies/timing.ini). Only in a report
// whose study has timings; they vary between machines, so the caption says which numbers a reader
// can compare.
#pragma once

#include <cstdint>
#include <map>
#include <optional>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

std::optional<Table> overhead_table(const StudyIndex& index,
                                    const std::map<std::int64_t, double>& wall_seconds);

} // namespace mhb
