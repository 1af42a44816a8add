// Grids of specs: braces in a spec stand for a set of values, and the spec for one variant per
// combination, e.g. `itlbo:tutorial={on,off},stepwise={on,off},obl={on,off}` is 8 specs and
// `pso:w={0.4,0.5,0.7}` is 3. The first braced key varies slowest, in the order written, so the
// variants keep a fixed, readable order. Nested braces, empty sets, a value listed twice and
// unbalanced braces are errors naming the spec.
//
// Integer ranges (`f=1-24`) are not expanded here: the registry expands those of parameters that
// declare them (Registry::expand), and a braced value may itself be such a range.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mhb {

struct GridVariant {
    std::string text; // one spec, without braces
    // The (key, value) chosen from each braced set, in the order written: what tells the variants
    // of one grid apart (labels are made from it).
    std::vector<std::pair<std::string, std::string>> varying;
};

// The most variants one grid may have (the product of its sets' sizes), checked before any is
// made: a line of a few dozen two-valued sets would otherwise ask for billions of specs.
inline constexpr std::size_t max_grid_variants = 100000;

// The variants of `text`; a text without braces is one variant with nothing varying.
// Throws std::invalid_argument naming the text and the fault.
std::vector<GridVariant> expand_grid(std::string_view text);

// Splits a list of specs given as one string, separated by spaces (as `--algorithms "a b"`);
// spaces inside braces do not separate (`pso:w={0.4, 0.5}` is one spec), nor do spaces inside
// '...' or "..." (kept with their quotes: `external:cmd='python3 model.py'` is one spec).
std::vector<std::string> split_spec_list(std::string_view text);

} // namespace mhb
