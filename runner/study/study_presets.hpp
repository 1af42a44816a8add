// Named studies (`mhbench run --study NAME`): the study files in scripts/studies/, compiled into
// the executable. Adding a preset is adding a file; its first comment line is its summary.
// Command-line options override a preset's values.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "runner/study/study.hpp"

namespace mhb {

struct StudyPreset {
    std::string name;    // the file's name without .ini
    std::string summary; // its first comment line, for `mhbench list studies` and `mhbench run --help`
    std::string origin;  // "scripts/studies/NAME.ini", named in errors
    std::string text;    // the file as shipped
    Study study;
};

// In the order of their names. A preset that does not parse is a std::logic_error (a test
// checks every one).
const std::vector<StudyPreset>& study_presets();

// Throws std::invalid_argument listing the known names when `name` is not one of them.
const StudyPreset& find_study_preset(std::string_view name);

} // namespace mhb
