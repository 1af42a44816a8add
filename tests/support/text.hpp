// Small text checks shared by the tests: whether a number prints as nan, how often a piece of text
// occurs (no std::regex: GCC 12 warns inside <regex> under the sanitizer builds).
#pragma once

#include <cctype>
#include <cstddef>
#include <string>
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

// How many times `what` occurs in `text`, overlapping occurrences included.
inline std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

} // namespace mhb::test_support
