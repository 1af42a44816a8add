// Fuzzes the spec language (problems/core/spec.hpp, problems/core/spec_grid.hpp) and its validation against
// the built-in registries: split_spec_list, expand_grid, Spec::parse, then Registry::minimal,
// normalised and expand of each variant. Bad input must give std::invalid_argument, never a crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/spec.hpp"
#include "problems/core/spec_grid.hpp"
#include "problems/problem_registry.hpp"

namespace {

template <class Registry> void validate(const Registry& registry, const mhb::Spec& spec) {
    try {
        const mhb::Spec minimal = registry.minimal(spec);
        const mhb::Spec normalised = registry.normalised(spec);
        // A normal form is a fixed point, and it reads back as written.
        if (registry.normalised(normalised).canonical() != normalised.canonical() ||
            mhb::Spec::parse(normalised.canonical()).canonical() != normalised.canonical() ||
            minimal.parameters.size() > normalised.parameters.size())
            std::abort();
    } catch (const std::invalid_argument&) {
    }
    // Ranges: only where a parameter declares them, so at most one range here bounds the work.
    std::size_t dashes = 0;
    for (const auto& [key, value] : spec.parameters)
        dashes += value.find('-', 1) != std::string::npos ? 1 : 0;
    if (dashes <= 1)
        try {
            (void)registry.expand(spec);
        } catch (const std::invalid_argument&) {
        }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    for (const std::string& item : mhb::split_spec_list(text)) {
        try {
            const auto variants = mhb::expand_grid(item);
            // The first variants are validated: a grid's variants differ only in values.
            for (std::size_t v = 0; v < variants.size() && v < 64; ++v) {
                const mhb::GridVariant& variant = variants[v];
                mhb::Spec spec;
                try {
                    spec = mhb::Spec::parse(variant.text);
                } catch (const std::invalid_argument&) {
                    continue;
                }
                if (mhb::Spec::parse(spec.canonical()).canonical() != spec.canonical())
                    std::abort(); // the canonical text reads back as itself
                validate(mhb::builtin_algorithms(), spec);
                validate(mhb::builtin_problems(), spec);
            }
        } catch (const std::invalid_argument&) {
        }
    }
    return 0;
}
