// context.ini read back: its `key = value` lines, for the report's pages (LaTeX and HTML) that show
// where and how a study was run.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mhb {

// The entries of context.ini in file order, key and value without the blanks at either end.
// Blank lines, comments (`#` or `;`) and lines without '=' are left out.
std::vector<std::pair<std::string, std::string>> context_entries(std::string_view text);

} // namespace mhb
