// The figures of a report: scripts/plot_study.py run on a budget's curve data by the first Python
// that can import matplotlib, as a child process (what a failure or a stop does: report.hpp).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>

#include "results/report/report.hpp"

namespace mhb {

enum class Figures { drawn_or_skipped, interrupted };

// Draws the figures of the report in `out_dir` (into out_dir/figures) unless options.stop is set.
// `note` gets what the HTML page must say about the figures (skipped, failed), empty when all went
// well.
Figures draw_figures(const ReportOptions& options, const std::filesystem::path& out_dir,
                     std::ostream& console, std::string& note);

} // namespace mhb
