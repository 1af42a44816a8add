#include "problems/core/spec.hpp"

#include <algorithm>
#include <stdexcept>

#include "problems/core/text_excerpt.hpp"

namespace mhb {
namespace {

bool is_name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.';
}

} // namespace

std::string_view trim_blanks(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

Spec Spec::parse(std::string_view text) {
    const std::string_view original = text;
    text = trim_blanks(text);
    const auto fail = [&](const std::string& why) {
        throw std::invalid_argument(quoted_excerpt(original) + ": " + why);
    };
    Spec spec;
    const auto colon = text.find(':');
    spec.name = std::string(trim_blanks(text.substr(0, colon)));
    if (spec.name.empty())
        fail("a name is missing (write name:key=value,...)");
    if (spec.name.find(',') !=
        std::string::npos) { // `--algorithms itlbo,pso`: a list, written as in other tools
        std::string spaced = spec.name;
        std::replace(spaced.begin(), spaced.end(), ',', ' ');
        fail("separate several with spaces, not commas: " + value_excerpt(spaced));
    }
    if (!std::all_of(spec.name.begin(), spec.name.end(), is_name_char))
        fail("name " + quoted_excerpt(spec.name) + " may only hold letters, digits, '_', '-' and '.'");
    if (colon == std::string_view::npos)
        return spec;
    std::string_view rest = text.substr(colon + 1);
    for (bool after_comma = false;; after_comma = true) {
        const auto comma = rest.find(',');
        const std::string_view item = trim_blanks(rest.substr(0, comma));
        const auto eq = item.find('=');
        if (eq == std::string_view::npos)
            fail(value_excerpt(item) + " is not key=value" +
                 (after_comma && !item.empty() && std::all_of(item.begin(), item.end(), is_name_char)
                      ? "; to name several components, separate them with spaces"
                      : ""));
        std::string key(trim_blanks(item.substr(0, eq)));
        std::string value(trim_blanks(item.substr(eq + 1)));
        if (key.empty())
            fail("a key is empty in " + quoted_excerpt(item));
        if (value.empty())
            fail("parameter " + quoted_excerpt(key) + " has no value");
        if (spec.find(key) != nullptr)
            fail("parameter " + quoted_excerpt(key) + " is given twice");
        spec.parameters.emplace_back(std::move(key), std::move(value));
        if (comma == std::string_view::npos)
            break;
        rest = rest.substr(comma + 1);
    }
    return spec;
}

std::string Spec::canonical() const {
    auto sorted = parameters;
    std::sort(sorted.begin(), sorted.end());
    std::string out = name;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        out += (i == 0 ? ':' : ',');
        out += sorted[i].first + '=' + sorted[i].second;
    }
    return out;
}

const std::string* Spec::find(std::string_view key) const {
    for (const auto& [k, v] : parameters)
        if (k == key)
            return &v;
    return nullptr;
}

} // namespace mhb
