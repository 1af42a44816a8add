#include "problems/core/spec_grid.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "problems/core/spec.hpp"

namespace mhb {
namespace {

// Splits at the commas that are not inside braces.
std::vector<std::string_view> split_top_level(std::string_view text) {
    std::vector<std::string_view> items;
    int depth = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '{')
            ++depth;
        else if (text[i] == '}')
            --depth;
        else if (text[i] == ',' && depth == 0) {
            items.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    }
    items.push_back(text.substr(start));
    return items;
}

} // namespace

std::vector<GridVariant> expand_grid(std::string_view text) {
    const std::string shown(trim_blanks(text));
    const auto fail = [&](const std::string& why) { throw std::invalid_argument("'" + shown + "': " + why); };
    // Braces must balance and never nest.
    int depth = 0;
    for (const char c : shown) {
        if (c == '{' && ++depth > 1)
            fail("nested braces are not allowed (a grid lists plain values: key={a,b,c})");
        if (c == '}' && --depth < 0)
            fail("a '}' has no matching '{'");
    }
    if (depth != 0)
        fail("a '{' is not closed");
    if (shown.find('{') == std::string::npos)
        return {GridVariant{shown, {}}};

    const auto colon = shown.find(':');
    if (colon == std::string::npos || shown.find('{') < colon)
        fail("braces belong in a parameter's value (name:key={a,b})");
    const std::string name = shown.substr(0, colon);
    // Each item is either fixed (`key=value`) or a set (`key={a,b}`).
    struct Item {
        std::string key;
        std::vector<std::string> values;
        bool braced = false;
    };
    std::vector<Item> items;
    for (const std::string_view raw : split_top_level(std::string_view(shown).substr(colon + 1))) {
        const std::string_view item = trim_blanks(raw);
        const auto eq = item.find('=');
        if (eq == std::string_view::npos || item.find('{') < eq)
            fail(std::string(item) + " is not key=value or key={a,b,...}");
        Item parsed;
        parsed.key = std::string(trim_blanks(item.substr(0, eq)));
        const std::string_view value = trim_blanks(item.substr(eq + 1));
        if (value.find('{') == std::string_view::npos) {
            parsed.values.emplace_back(value);
        } else {
            if (value.front() != '{' || value.back() != '}')
                fail("parameter '" + parsed.key + "': a set is written {a,b,...} and nothing else");
            parsed.braced = true;
            const std::string_view inside = value.substr(1, value.size() - 2);
            if (trim_blanks(inside).empty())
                fail("parameter '" + parsed.key + "': the set {} is empty");
            for (const std::string_view v : split_top_level(inside)) {
                const std::string one(trim_blanks(v));
                if (one.empty())
                    fail("parameter '" + parsed.key + "': the set has an empty value");
                if (std::find(parsed.values.begin(), parsed.values.end(), one) != parsed.values.end())
                    fail("parameter '" + parsed.key + "': value '" + one + "' is listed twice in the set");
                parsed.values.push_back(one);
            }
        }
        items.push_back(std::move(parsed));
    }
    std::size_t count = 1;
    for (const auto& item : items) {
        count *= item.values.size(); // at most max_grid_variants times the text's length: no overflow
        if (count > max_grid_variants)
            fail("the grid has more than " + std::to_string(max_grid_variants) +
                 " variants (the product of its sets' sizes)");
    }

    std::vector<GridVariant> out{GridVariant{name, {}}};
    for (const auto& item : items) {
        std::vector<GridVariant> next;
        next.reserve(out.size() * item.values.size());
        for (const auto& partial : out)
            for (const auto& v : item.values) {
                GridVariant g = partial;
                g.text += (g.text == name ? ":" : ",") + item.key + "=" + v;
                if (item.braced)
                    g.varying.emplace_back(item.key, v);
                next.push_back(std::move(g));
            }
        out = std::move(next);
    }
    return out;
}

std::vector<std::string> split_spec_list(std::string_view text) {
    std::vector<std::string> out;
    std::string current;
    int depth = 0;
    char quote = 0;
    for (const char c : text) {
        if (quote != 0) {
            current += c;
            if (c == quote)
                quote = 0;
            continue;
        }
        if (c == '\'' || c == '"')
            quote = c;
        if (c == '{')
            ++depth;
        else if (c == '}')
            --depth;
        const bool space = c == ' ' || c == '\t' || c == '\n' || c == '\r';
        if (space && depth <= 0) {
            if (!current.empty())
                out.push_back(std::move(current));
            current.clear();
        } else if (!space) {
            current += c;
        }
    }
    if (!current.empty())
        out.push_back(std::move(current));
    return out;
}

} // namespace mhb
