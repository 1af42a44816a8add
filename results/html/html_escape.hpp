// Text for the HTML report (results/html/html_report.hpp): escaping, and anchors built from names.
#pragma once

#include <string>
#include <string_view>

namespace mhb {

// `text` with & < > " ' as character references: safe in element content and in quoted attributes.
std::string html_escape(std::string_view text);

// An anchor (id attribute, #fragment) from a name: ASCII letters, digits, '_' and '-' are kept,
// every other byte becomes '-', so "table2_fitness" stays itself and "pmsm:load=2" is "pmsm-load-2".
// Distinct names may meet ("a:b", "a=b"); callers prefix a section so that a page's ids stay unique.
std::string html_anchor(std::string_view name);

} // namespace mhb
