// Export of a study's runs in the IOHprofiler format (IOHexperimenter's "analyzer" logger, v2: one
// .json per problem and algorithm plus a .dat with the runs' improvements), so that IOHanalyzer
// loads them without conversion. Layout, one folder per algorithm as IOHanalyzer expects:
//   <dir>/<algorithm>/IOHprofiler_f<id>_<problem>.json
//   <dir>/<algorithm>/data_f<id>_<problem>/IOHprofiler_f<id>_DIM<d>.dat
// Problems are numbered 1, 2, ... in study order (function_id); all runs are instance 1 (mhbench
// repeats runs on one problem instance). The .dat rows are the improvements of best-so-far f as
// mhbench recorded them (end of each iteration and the evaluation checkpoints), so an improvement's
// evaluation count is where it was recorded, which can be later than where it happened.
// An algorithm is named by its display label, with its full spec in "info".
#pragma once

#include <filesystem>

#include "results/study_index.hpp"

namespace mhb {

// Writes the export under `dir`; returns the number of files written.
std::size_t write_ioh_export(const StudyIndex& index, const std::filesystem::path& dir);

} // namespace mhb
