// What `mhbench run --dry-run` prints: the expanded study (algorithms with labels and canonical
// specs, problems, budgets, runs), its estimated evaluations and time (runner/study/calibration.hpp),
// and what the output directory holds. Nothing is run but the short calibration runs, and
// nothing is written.
#pragma once

#include <filesystem>
#include <string>

#include "runner/study/study.hpp"

namespace mhb {

// `report` and `figures`: what the run does after the runs (--no-report, --no-figures), estimated too.
std::string dry_run_text(const PreparedStudy& study, const std::filesystem::path& dir, int threads,
                         bool report = true, bool figures = true);

} // namespace mhb
