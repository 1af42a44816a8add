// A budget's verdict (results/analysis/verdict.hpp) as tables, for the top of the HTML page: the
// ranking across problems ("verdict_across", two or more problems), the components' main effects
// ("verdict_effects", factorial designs) and each problem's ranking with its test against the best
// ("verdict"). They are not among the report's files: the console prints the same verdict, and the
// full tables (summary, tests, comparison, ...) hold everything it sums up.
#pragma once

#include <vector>

#include "results/analysis/verdict.hpp"
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

std::vector<Table> verdict_tables(const BudgetVerdict& verdict);

} // namespace mhb
