// A table (results/table_model/table.hpp) as CSV, for other tools: a header line and one line per body
// row, each cell at full precision (TableCell::value where set), an undefined value as an empty
// field; no footer rows, so that every row is of one kind.
#pragma once

#include <string>

#include "results/table_model/table.hpp" // a renderer sees tables, never runs

namespace mhb {

std::string render_csv(const Table& table);

} // namespace mhb
