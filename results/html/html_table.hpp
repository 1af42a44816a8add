// One report table (results/table_model/table.hpp) as HTML for the HTML report: its title as a heading, its
// caption, and a plain <table> that reads well without JavaScript (the page's script makes the
// headers sort; see html_page_assets.hpp). Every text is escaped.
#pragma once

#include <string>

#include "results/table_model/table.hpp" // a renderer sees tables, never runs

namespace mhb {

// `anchor` is the section's id (the table of contents links to it); `heading_level` the <hN> of the
// title (2..6). A cell whose CSV value differs from its text carries it as data-value, so that
// sorting uses full precision ("0.0040664" shown, "0.004066412..." sorted).
std::string render_html_table(const Table& table, const std::string& anchor, int heading_level);

} // namespace mhb
