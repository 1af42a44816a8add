// One report table (results/table_model/table.hpp) as HTML for the HTML report: its title as a heading, its
// caption, and a plain <table> that reads well without JavaScript (the page's script makes the
// headers sort; see html_page_assets.hpp). Every text is escaped.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "results/table_model/table.hpp" // a renderer sees tables, never runs

namespace mhb {

// `anchor` is the section's id (the table of contents links to it); `heading_level` the <hN> of the
// title (2..6). A cell whose CSV value differs from its text carries it as data-value, so that
// sorting uses full precision ("0.0040664" shown, "0.004066412..." sorted). The columns that decide
// (Result, Reading, p (Holm), vs best, ...) come right after the leading key columns (Problem,
// Algorithm, ...), so that a wide table shows them without scrolling, and the first column stays in
// view when it scrolls sideways (the page's style). An algorithm's label found in `colours` (its
// figures' colour, html_figures.hpp) gets a swatch of that colour.
std::string render_html_table(const Table& table, const std::string& anchor, int heading_level,
                              const std::map<std::string, std::string>& colours = {});

// The order in which the page shows the table's columns (indices into its header).
std::vector<std::size_t> html_column_order(const std::vector<std::string>& header);

} // namespace mhb
