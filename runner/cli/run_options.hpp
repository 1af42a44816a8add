// `mhbench run`'s command line: its options (the study options of runner/study/study_options.hpp
// and those of running), its help, and the study it describes: a preset or a study file to start
// from, then the options given, on top.
#pragma once

#include <boost/program_options.hpp>
#include <string>
#include <vector>

#include "runner/study/study.hpp"

namespace mhb::cli {

boost::program_options::options_description make_run_options();
void print_run_help(const boost::program_options::options_description& options);

// The study to start from: a preset, a study file, or an empty study; `name` is the preset's, or
// "study". False if none could be read (the reason in `errors`). A study file's errors are all
// kept, each with its line.
bool load_base_study(const boost::program_options::variables_map& vm, Study& study, std::string& name,
                     std::vector<std::string>& errors);

// The study options given on the command line, on top of the base study.
void apply_study_options(const boost::program_options::variables_map& vm, Study& study,
                         std::vector<std::string>& errors);

} // namespace mhb::cli
