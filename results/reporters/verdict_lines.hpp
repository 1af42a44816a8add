// A budget's verdict (results/analysis/verdict.hpp) as the console's few lines: what `mhbench run`
// and `mhbench report` print instead of every table (`--tables` prints those as well). The lines
// fit a screen: each is at most verdict_width columns, and the verdict at most `max_lines` lines,
// by dropping detail in a fixed order. First the problem's ranking (one problem), the components'
// effects pooled over problems and the ranking across problems (cut to its best when long); then
// per problem the ranking with median gap and test against the best, or, when those do not fit,
// one line per problem (its best and those not significantly different from it), or else one
// line saying which tables hold them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "results/analysis/verdict.hpp"

namespace mhb {

inline constexpr std::size_t verdict_width = 100;

std::vector<std::string> verdict_lines(const BudgetVerdict& verdict, std::size_t max_lines);

} // namespace mhb
