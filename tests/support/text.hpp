// Small text checks shared by the tests (no std::regex: GCC 12 warns inside <regex> under the
// sanitizer builds).
#pragma once

#include <cctype>
#include <string_view>

namespace mhb::test_support {

// True when "nan" or "-nan", as printf writes them, stands in `text` as a word (not inside a
// longer word; "NaN" in a message does not count).
inline bool prints_nan(std::string_view text) {
    const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
    for (auto at = text.find("nan"); at != std::string_view::npos; at = text.find("nan", at + 1)) {
        const bool starts = at == 0 || !letter(text[at - 1]);
        const bool ends = at + 3 == text.size() || !letter(text[at + 3]);
        if (starts && ends)
            return true;
    }
    return false;
}

} // namespace mhb::test_support
