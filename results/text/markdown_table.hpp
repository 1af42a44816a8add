// A table (results/table_model/table.hpp) in Markdown, for the console and the report's .md files: a
// heading with its title, text columns left-aligned and number columns right-aligned, the footer
// rows (w/t/l) under the body, the caption after it as notes.
#pragma once

#include <string>

#include "results/table_model/table.hpp" // a renderer sees tables, never runs

namespace mhb {

std::string render_markdown(const Table& table);

} // namespace mhb
