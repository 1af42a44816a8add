#include "runner/study/study_presets.hpp"

#include <algorithm>
#include <stdexcept>

#include "problems/core/did_you_mean.hpp"
#include "problems/core/text_excerpt.hpp"
#include "runner/study/study_file.hpp"

namespace mhb {
namespace detail {
// Generated from scripts/studies/*.ini (runner/study/study_preset_files.cpp.in).
const std::vector<std::pair<std::string_view, std::string_view>>& study_preset_files();
} // namespace detail

const std::vector<StudyPreset>& study_presets() {
    static const std::vector<StudyPreset> presets = [] {
        std::vector<StudyPreset> out;
        for (const auto& [name, text] : detail::study_preset_files()) {
            StudyPreset p;
            p.name = std::string(name);
            p.origin = "scripts/studies/" + p.name + ".ini";
            p.text = std::string(text);
            p.summary = study_file_summary(text);
            try {
                p.study = parse_study_ini(text, p.origin);
            } catch (const std::exception& e) {
                throw std::logic_error(std::string("a shipped preset does not parse: ") + e.what());
            }
            out.push_back(std::move(p));
        }
        std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
        return out;
    }();
    return presets;
}

const StudyPreset& find_study_preset(std::string_view name) {
    std::vector<std::string> known;
    for (const auto& p : study_presets()) {
        if (p.name == name)
            return p;
        known.push_back(p.name);
    }
    throw std::invalid_argument("unknown study " + quoted_excerpt(name) + suggestion_or_known(name, known));
}

} // namespace mhb
