// study.ini: a study written down so that `mhbench run --study-file DIR/study.ini` runs it again.
// The syntax is Boost.Program_options' config-file syntax (`key = value`, `#` comments), with the
// keys of `mhbench run`'s options:
//
//   algorithm = pso:w=0.7        one line per algorithm, in order (a line may hold several,
//                                separated by spaces, as on the command line)
//   problem = sphere:dim=10      one line per problem spec, in order (ranges kept as written)
//   runs = 20
//   seed = 1
//   iterations = 150             and/or
//   evaluations = 10000
//   target = 1e-8                optional
//
// The thread count and the output directory are deliberately absent: they do not change the
// results, so a study resumed or repeated with other values is the same study. The text is a
// pure function of the study (no dates, no versions), since StudyWriter compares it byte for byte
// to decide whether a directory holds the same study.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "runner/study.hpp"

namespace mhb {

std::string study_ini(const Study& study);

// Parses study.ini text with Boost.Program_options' config-file parser. Throws
// std::invalid_argument naming `origin` and the key on a syntax error, an unknown key, a repeated
// single-valued key or a malformed number. Specs are checked later, by
// prepare_study().
Study parse_study_ini(std::string_view text, const std::string& origin);

// Reads and parses a study file; a file that cannot be read is a std::runtime_error.
Study read_study_file(const std::filesystem::path& path);

} // namespace mhb
