// Study files: a study written down, in the command line's own words. The syntax is
// Boost.Program_options' config-file syntax, one `key = value` per line, with the long names of
// `mhbench run`'s study options (runner/study/study_options.hpp):
//
//   # The paper's ablation: ITLBO's three components on and off   (first comment: the summary)
//   algorithms = itlbo:tutorial={on,off},stepwise={on,off},obl={on,off}
//   problems = pmsm:speed=2500,load=2         an indented line continues the line above
//              pmsm:speed=2500,load=3          (so does a trailing backslash)
//              pmsm:speed=2000,load=2
//   runs = 20
//   seed = 1
//   seeds = common                             or per-algorithm
//   budget = iterations=150                    several budgets: one line each
//   budget = evaluations=15050
//   iterations = 150                           or the single-budget keys, as on the command line
//   target = 1e-8                              optional
//   budget = evaluations=10000*dim             evaluations by dimension
//   (results/analysis/dimension_budget.hpp) protocol = cec2017                         a CEC protocol's
//   tables and files (results/protocols/) plugins = /path/mine.so                    plug-in
//   modules naming components (runner/plugins/plugin_loader.hpp)
//
// `#` starts a comment; a UTF-8 byte-order mark is skipped. Every error names the file and the
// line. Threads and the output directory are deliberately absent: they do not change results,
// so a study resumed or repeated with other values is the same study.
//
// study_ini() writes a prepared study back: grids expanded, specs canonical, labels kept. Its text
// is a pure function of the study (no dates, no versions), since StudyWriter compares it byte for
// byte to decide whether a directory holds the same study.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "runner/study/study.hpp"

namespace mhb {

std::string study_ini(const Study& study);

// Parses study-file text on top of `study` (a default Study for a file on its own). Errors are
// appended to `errors`, each as "ORIGIN:LINE: what is wrong"; what could be read is applied. A
// text of several lines none of which is `key = value` is one error ("ORIGIN: is not a study
// file (...)").
// Returns false when a line is not `key = value`: what the study lacks then says nothing new.
bool parse_study_file(std::string_view text, const std::string& origin, Study& study,
                      std::vector<std::string>& errors);

// The same, throwing std::invalid_argument with every error (one per line) if there is any.
Study parse_study_ini(std::string_view text, const std::string& origin);

// The text of a study file; std::runtime_error naming the file and the reason (a directory, a
// missing file, no permission) when it cannot be read.
std::string read_study_text(const std::filesystem::path& path);

// Reads and parses a study file; a file that cannot be read is a std::runtime_error naming it
// and the reason.
Study read_study_file(const std::filesystem::path& path);

// The first comment line of a study file, without '#' (a preset's one-line summary).
std::string study_file_summary(std::string_view text);

} // namespace mhb
