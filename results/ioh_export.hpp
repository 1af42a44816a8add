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
// Non-finite values: the format has no inf (JSON has none; IOHanalyzer reads raw_y as numbers), so
// a recorded point whose f is +inf (or -inf) is left out of the .dat, a run none of whose points is
// finite (it ended at +inf) is left out of the export, and both are counted for the console; a
// non-finite coordinate of best x is null in the JSON. Failed runs are never exported.
#pragma once

#include <cstddef>
#include <filesystem>

#include "results/study_index.hpp"

namespace mhb {

struct IohExportSummary {
    std::size_t files = 0;           // files written
    std::size_t runs_left_out = 0;   // runs without a finite value (ended at +inf)
    std::size_t points_left_out = 0; // non-finite points of the exported runs
};

// Writes the export under `dir`.
IohExportSummary write_ioh_export(const StudyIndex& index, const std::filesystem::path& dir);

} // namespace mhb
