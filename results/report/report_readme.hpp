// report/README.md: the data dictionary written with every report, so that a reader of the CSV
// files alone knows what each column holds, in which unit, how it was computed and how it rounds.
// The data files (curves, final values, target hits, critical difference, effect means, relative
// gaps) have
// fixed columns, described here once; each table's CSV is described from the table itself (its
// title, columns and caption), so the dictionary cannot drift from what was written.
#pragma once

#include <string>
#include <vector>

#include "results/table_model/table.hpp"

namespace mhb {

// Which optional files a budget's report directory holds.
struct ReportFiles {
    std::vector<std::string> formats; // of the tables, the extensions of their files: "md", "tex", ...
    bool critical_difference = false;
    bool effect_means = false;
    bool relative_gaps = false;
    bool final_points = false; // f0's structural-bias audit
    bool bayesian = false;     // bayesian_probabilities.csv and bayesian_samples.csv
    bool cec = false;
    bool figures = false;
    bool budget_txt = false;
    bool combined = true; // report.md, report.tex and index.html sit beside the files (one budget)
};

// The README.md of one budget's report directory.
std::string report_readme(const std::vector<Table>& tables, const ReportFiles& files);

// The README.md on top of a report with several budgets, each in its folder.
std::string budgets_readme(const std::vector<std::string>& budgets, const std::vector<std::string>& folders);

} // namespace mhb
