// `mhbench report`: everything rebuilt from a finished study directory alone. Writes into the
// report directory the tables (Markdown, LaTeX, CSV; the paper's Tables 2-4 for PMSM problems, the
// statistics tables for any problem, the effects of each component for variants forming a 2^k
// on/off design), the curve data (CSV) and, when a Python with matplotlib is found, the figures
// (figures/*.pdf and *.png, drawn by scripts/plot_study.py from the curve data), the runs in
// the IOHprofiler format (ioh/, for IOHanalyzer), and index.html, one self-contained page with
// every table and figure (a section per budget when there are several).
// A study with several budgets gets all of that once per budget, in <report>/<budget slug>/ (see
// budget_slug), with budgets.csv, report.md and report.tex on top; a study with one budget keeps
// the flat layout. Prints the Markdown tables to the console. The runner calls it at the end of
// `mhbench run`. Each of those outputs but the curve data and the figures is a reporter
// (results/reporters/reporter.hpp), registered by name: this room decides when, they write.
// Failed runs are left out of every statistic and +inf final values (legal: the worst) are kept;
// the console summary, the captions and the figures say what was left out. Figures are a
// convenience: a plotting script that fails is reported in one line on `errors` ("figures
// failed: ...", its whole output kept in figures/plot_study.log) and the report still succeeds.
// The script runs as a child process tied to this one (results/report/child_process.hpp): killing
// mhbench, even with SIGKILL, ends it and whatever it started, and it writes each figure under a
// temporary name then renames it, so a stop at any moment leaves whole files only (every other
// report file is written by write_file_atomically). Ctrl-C (SIGINT) or SIGTERM while it draws
// stops it quietly: the report says so in one line on `errors` and returns interrupted
// (ReportOutcome).
#pragma once

#include <atomic>
#include <filesystem>
#include <iostream>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "results/analysis/bayesian_comparisons.hpp" // default_log10_rope
#include "results/exports/ioh_export.hpp"
#include "results/reporters/reporter_registry.hpp"
#include "results/store/study_data.hpp"

namespace mhb {

struct ReportOptions {
    std::filesystem::path out_dir;        // empty: <study directory>/report
    std::optional<std::string> reference; // algorithm to test against (spec, label or unique name);
                                          // at a budget that did not run it, the default there
    double alpha = 0.05;                  // significance level of the markers
    // Half-width of the ROPE of the Bayesian signed-rank tests (--rope): decades of f - f*; and in
    // units of f for problems without a known f* (--raw-rope; none: no ROPE there).
    double rope = default_log10_rope;
    std::optional<double> raw_rope;
    // Table formats, by reporter name (results/reporters/): --format; every export is always written.
    std::set<std::string> formats = default_table_formats();
    bool figures = true;
    // The console prints every table in Markdown (--tables), not only the verdict of each budget.
    bool console_tables = false;
    IohPrecision ioh_precision = IohPrecision::logger; // raw_y of ioh/*.dat
    std::filesystem::path plot_script;                 // scripts/plot_study.py; empty: figures are skipped
    // Interpreters tried in order; the first that can `import matplotlib` draws the figures.
    std::vector<std::string> python_candidates = {"/usr/bin/python3", "python3"};
    // Where a failure of the figures is reported (one line each); never nullptr.
    std::ostream* errors = &std::cerr;
    // When set and true, no figure is started (the CLI passes its Ctrl-C flag): the outcome is
    // interrupted, as if the figures had been stopped.
    const std::atomic<bool>* stop = nullptr;
};

struct ReportOutcome {
    // The figures were stopped (SIGINT or SIGTERM while the script ran, or `stop`): every table,
    // the curve data and the IOH export are written, the figures of that budget and of the budgets
    // after it are not (or only some), and `mhbench report` draws them. `errors` got one line:
    // "figures interrupted; run `mhbench report DIR` to draw them".
    bool interrupted = false;
    // The page `--open` shows: index.html, every table and figure on one self-contained page
    // (results/reporters/html_reporter.cpp).
    std::filesystem::path html;
};

// Checks the options (std::invalid_argument naming the option), then writes the report.
// Throws std::runtime_error when a file cannot be written.
ReportOutcome build_report(const StudyData& study, const ReportOptions& options, std::ostream& console);

// The first candidate interpreter that can import matplotlib, if any (each is run without a shell;
// a name without '/' is searched in PATH).
std::optional<std::string> find_matplotlib_python(const std::vector<std::string>& candidates);

} // namespace mhb
