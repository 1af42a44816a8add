// Fuzzes the study-file reader (runner/study/study_file.hpp): any text is read, with its errors listed.
// An error-free study of a bounded size is also prepared (validated and built, not run), must give
// std::invalid_argument or a study, and its study.ini must read back to the same study.ini.
// PMSM problems are validated but not built (see problems() below).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "problems/core/spec.hpp"
#include "problems/core/spec_grid.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"

namespace {

constexpr std::size_t max_text = 4096;     // bytes of study file
constexpr std::size_t max_components = 50; // algorithms or problems, grids and ranges expanded

// How many components `specs` stand for once grids and integer ranges are expanded (an over-estimate:
// every `a-b` value counts as a range), saturating above max_components.
std::size_t component_count(const std::vector<std::string>& specs) {
    std::size_t total = 0;
    for (const auto& text : specs) {
        std::vector<mhb::GridVariant> variants;
        try {
            variants = mhb::expand_grid(text);
        } catch (const std::invalid_argument&) {
            continue; // prepare_study reports it
        }
        for (const auto& variant : variants) {
            std::size_t count = 1;
            try {
                for (const auto& [key, value] : mhb::Spec::parse(variant.text).parameters) {
                    const auto dash = value.find('-', 1);
                    if (dash == std::string::npos)
                        continue;
                    const long long lo = std::strtoll(value.substr(0, dash).c_str(), nullptr, 10);
                    const long long hi = std::strtoll(value.substr(dash + 1).c_str(), nullptr, 10);
                    if (hi < lo)
                        continue; // an empty range: an error, not work
                    const double width = static_cast<double>(hi) - static_cast<double>(lo) + 1.0;
                    if (width > static_cast<double>(max_components))
                        return max_components + 1;
                    count *= static_cast<std::size_t>(width);
                    if (count > max_components)
                        return max_components + 1;
                }
            } catch (const std::invalid_argument&) {
            }
            total += count;
            if (total > max_components)
                return max_components + 1;
        }
    }
    return total;
}

// The built-in problems, PMSM's factory replaced by a cheap stand-in: a pmsm spec is still
// validated parameter by parameter, but no drive is simulated (a second per problem) and no `data=`
// file named by the fuzzer is read (such as /dev/zero, which never ends). So is `external`'s: a
// fuzzer must never run the commands it writes.
const mhb::ProblemRegistry& problems() {
    static const mhb::ProblemRegistry registry = [] {
        mhb::ProblemRegistry out(mhb::builtin_problems().kind());
        for (auto entry : mhb::builtin_problems().entries()) {
            if (entry.name == "pmsm" || entry.name == "external")
                entry.factory = [](const mhb::ParameterValues&) {
                    return mhb::builtin_problems().create("sphere:dim=4");
                };
            out.add(std::move(entry));
        }
        return out;
    }();
    return registry;
}

// The built-in optimisers, `external`'s factory replaced by random search's (see problems()).
const mhb::AlgorithmRegistry& algorithms() {
    static const mhb::AlgorithmRegistry registry = [] {
        mhb::AlgorithmRegistry out(mhb::builtin_algorithms().kind());
        for (auto entry : mhb::builtin_algorithms().entries()) {
            if (entry.name == "external")
                entry.factory = [](const mhb::ParameterValues&) {
                    return mhb::builtin_algorithms().create("random-search");
                };
            out.add(std::move(entry));
        }
        return out;
    }();
    return registry;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > max_text)
        return 0;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    mhb::Study study;
    std::vector<std::string> errors;
    mhb::parse_study_file(text, "fuzz.ini", study, errors);
    (void)mhb::study_file_summary(text);
    if (!errors.empty() || component_count(study.algorithms) > max_components ||
        component_count(study.problems) > max_components)
        return 0;
    std::string ini;
    try {
        const mhb::PreparedStudy prepared = mhb::prepare_study(study, algorithms(), problems());
        if (prepared.run_count() < 1)
            std::abort();
        ini = mhb::study_ini(prepared.study);
    } catch (const std::invalid_argument&) {
        return 0;
    }
    // The study.ini a study directory stores reads back as the same study (parse_study_ini throws
    // if it does not read at all, which is as much a finding).
    if (mhb::study_ini(mhb::parse_study_ini(ini, "study.ini")) != ini)
        std::abort();
    return 0;
}
