// User text as echoed in an error message: at most 40 characters of it, so that a 1 MB bad cell
// or value gives one readable line, and control bytes (a stray byte-order mark's neighbours, a
// tab, a NUL) made visible as \xNN. Every reader and validator that quotes what the user wrote
// goes through these two functions.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace mhb {

inline constexpr std::size_t excerpt_max_characters = 40;

namespace detail {

// `text` with control bytes escaped, cut to `limit` characters (a UTF-8 sequence is never split).
inline std::string visible_prefix(std::string_view text, std::size_t limit, bool& cut) {
    std::string out;
    std::size_t shown = 0;
    cut = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        const bool continuation = (byte & 0xC0U) == 0x80U; // part of the character before
        if (!continuation && shown == limit) {
            cut = true;
            break;
        }
        if (byte < 0x20U || byte == 0x7FU) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", static_cast<unsigned>(byte));
            out += escaped;
        } else {
            out += text[i];
        }
        if (!continuation)
            ++shown;
    }
    return out;
}

inline std::size_t character_count(std::string_view text) {
    std::size_t n = 0;
    for (const char c : text)
        n += (static_cast<unsigned char>(c) & 0xC0U) != 0x80U ? 1 : 0;
    return n;
}

inline bool is_plain(std::string_view text) {
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20U || byte == 0x7FU)
            return false;
    }
    return true;
}

} // namespace detail

// `'text'`, or for longer text `'first 37 characters...' (N characters)`.
inline std::string quoted_excerpt(std::string_view text) {
    const std::size_t n = detail::character_count(text);
    bool cut = false;
    const std::string shown =
        detail::visible_prefix(text, n > excerpt_max_characters ? excerpt_max_characters - 3 : n, cut);
    if (!cut)
        return "'" + shown + "'";
    return "'" + shown + "...' (" + std::to_string(n) + " characters)";
}

// A value as written after `key = `: unquoted when it is short and plain (`runs = many`), else as
// quoted_excerpt.
inline std::string value_excerpt(std::string_view text) {
    if (detail::character_count(text) <= excerpt_max_characters && detail::is_plain(text))
        return std::string(text);
    return quoted_excerpt(text);
}

} // namespace mhb
