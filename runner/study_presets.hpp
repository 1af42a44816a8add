// Named studies (`mhbench run --study NAME`), kept in one small table so that adding one is one
// entry in study_presets.cpp. Command-line options override a preset's values.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "runner/study.hpp"

namespace mhb {

struct StudyPreset {
    std::string name;
    std::string summary; // one line for `mhbench list studies` and `mhbench run --help`
    Study study;
};

const std::vector<StudyPreset>& study_presets();

// Throws std::invalid_argument listing the known names when `name` is not one of them.
const StudyPreset& find_study_preset(std::string_view name);

} // namespace mhb
