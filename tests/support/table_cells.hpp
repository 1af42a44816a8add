// Report table cells built by their fields' names, for the tests of the HTML tables and report.
#pragma once

#include <string>

#include "results/table_model/table.hpp"

namespace mhb::test_support {

// A cell by its fields' names (TableCell may grow more fields).
inline TableCell cell(const std::string& text, const std::string& value, bool bold) {
    TableCell c = text_cell(text);
    c.value = value;
    c.bold = bold;
    return c;
}

} // namespace mhb::test_support
