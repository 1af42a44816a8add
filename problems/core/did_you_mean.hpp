// "Did you mean": the names a misspelt one was probably meant to be, for the one-line errors of
// every lookup by name (algorithms, problems, parameters, study presets, study-file keys, command
// options). A name is close when few single-character edits turn one into the other, case aside;
// a suggestion replaces the full list of names, which `mhbench list` prints.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace mhb {

// The number of insertions, deletions, substitutions and swaps of two neighbouring characters
// that turn `a` into `b` (the optimal string alignment distance), letters compared case-blind.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidates nearest `name` when they are near enough to be what was meant: at most 1 edit
// for a name of up to 4 characters, 2 up to 8, 3 beyond, and fewer than the name has characters; at
// most three, in the candidates' order.
// A name of three or more characters that begins exactly one candidate is taken as that candidate
// cut short (`lshade-cn` for `lshade-cnepsin`, not `lshade`). Empty when nothing is near.
std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates);

// "did you mean 'itlbo'?" or "did you mean 'tlbo' or 'itlbo'?"; empty when `suggestions` is.
std::string did_you_mean(const std::vector<std::string>& suggestions);

// The tail of an "unknown NAME" error: "; did you mean 'itlbo'?" when a candidate is near,
// otherwise "; known: a, b, c" (or "; known: none").
std::string suggestion_or_known(std::string_view name, const std::vector<std::string>& candidates);

} // namespace mhb
