#include "results/html/html_svg.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "results/html/html_escape.hpp"

namespace mhb {

namespace {

bool starts_with(std::string_view text, std::size_t at, std::string_view prefix) {
    return text.compare(at, prefix.size(), prefix) == 0;
}

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// The end (one past) of what starts at `at` and ends with `terminator`; the text's end if it never does.
std::size_t skip_past(std::string_view text, std::size_t at, std::string_view terminator) {
    const std::size_t end = text.find(terminator, at);
    return end == std::string_view::npos ? text.size() : end + terminator.size();
}

// The start of the root element: "<svg" followed by a space, '>' or '/'.
std::size_t find_root(std::string_view text) {
    for (std::size_t at = text.find("<svg"); at != std::string_view::npos; at = text.find("<svg", at + 1)) {
        const std::size_t next = at + 4;
        if (next < text.size() && (is_space(text[next]) || text[next] == '>' || text[next] == '/'))
            return at;
    }
    return std::string_view::npos;
}

struct Attribute {
    std::string name;
    std::string value;
    bool has_value = false;
};

// Every "url(#x" in an attribute value (clip-path, fill, style) becomes "url(#<prefix>-x".
std::string prefix_url_references(const std::string& value, const std::string& prefix) {
    std::string out;
    std::size_t from = 0;
    for (std::size_t at = value.find("url(#"); at != std::string::npos; at = value.find("url(#", from)) {
        out.append(value, from, at + 5 - from).append(prefix).append("-");
        from = at + 5;
    }
    return out.append(value, from, std::string::npos);
}

bool is_href(const std::string& name) {
    return name == "href" || (name.size() > 5 && name.compare(name.size() - 5, 5, ":href") == 0);
}

// The attribute as it goes into the page; nullopt-like empty name when it is dropped.
Attribute rewrite(Attribute a, const std::string& prefix) {
    if (a.name.rfind("xmlns", 0) == 0)
        return {};
    if (a.name == "id") {
        a.value = prefix + "-" + a.value;
        return a;
    }
    if (is_href(a.name) || a.name == "src") {
        if (a.value.rfind('#', 0) == 0)
            a.value = "#" + prefix + "-" + a.value.substr(1);
        else if (a.value.rfind("data:", 0) != 0) // an embedded raster image stays; a link goes
            return {};
        return a;
    }
    if (a.value.find("url(") != std::string::npos)
        a.value = prefix_url_references(a.value, prefix);
    return a;
}

// Parses the tag starting at `at` ('<' then a name); returns one past its '>'.
std::size_t parse_tag(std::string_view text, std::size_t at, std::string& name,
                      std::vector<Attribute>& attributes, bool& self_closing) {
    std::size_t i = at + 1;
    const std::size_t name_start = i;
    while (i < text.size() && !is_space(text[i]) && text[i] != '>' && text[i] != '/')
        ++i;
    name.assign(text.substr(name_start, i - name_start));
    attributes.clear();
    self_closing = false;
    while (i < text.size()) {
        while (i < text.size() && is_space(text[i]))
            ++i;
        if (i >= text.size())
            break;
        if (text[i] == '>')
            return i + 1;
        if (text[i] == '/') {
            self_closing = true;
            ++i;
            continue;
        }
        Attribute a;
        const std::size_t start = i;
        while (i < text.size() && !is_space(text[i]) && text[i] != '=' && text[i] != '>' && text[i] != '/')
            ++i;
        a.name.assign(text.substr(start, i - start));
        while (i < text.size() && is_space(text[i]))
            ++i;
        if (i < text.size() && text[i] == '=') {
            ++i;
            while (i < text.size() && is_space(text[i]))
                ++i;
            a.has_value = true;
            if (i < text.size() && (text[i] == '"' || text[i] == '\'')) {
                const char quote = text[i++];
                const std::size_t end = std::min(text.find(quote, i), text.size());
                a.value.assign(text.substr(i, end - i));
                i = end + 1;
            } else {
                const std::size_t value_start = i;
                while (i < text.size() && !is_space(text[i]) && text[i] != '>')
                    ++i;
                a.value.assign(text.substr(value_start, i - value_start));
            }
        }
        if (!a.name.empty())
            attributes.push_back(std::move(a));
    }
    return text.size();
}

std::string attribute_value(const std::string& value) {
    std::string out = "\"";
    for (char c : value)
        out += c == '"' ? std::string("&quot;") : std::string(1, c);
    return out + "\"";
}

} // namespace

std::string inline_svg(std::string_view svg_text, const std::string& prefix, const std::string& title) {
    const std::size_t root = find_root(svg_text);
    const std::size_t close = svg_text.rfind("</svg>");
    if (root == std::string_view::npos || close == std::string_view::npos || close < root)
        throw std::runtime_error("no <svg> element");
    const std::string_view text = svg_text.substr(root, close + 6 - root);
    const bool has_title = text.find("<title") != std::string_view::npos;

    std::string out;
    out.reserve(text.size());
    std::string name;
    std::vector<Attribute> attributes;
    bool self_closing = false;
    bool first_tag = true;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] != '<') {
            const std::size_t next = std::min(text.find('<', i), text.size());
            out.append(text.substr(i, next - i));
            i = next;
        } else if (starts_with(text, i, "<!--")) {
            i = skip_past(text, i, "-->"); // comments say nothing the reader sees
        } else if (starts_with(text, i, "<![CDATA[")) {
            const std::size_t end = skip_past(text, i, "]]>");
            out.append(text.substr(i, end - i));
            i = end;
        } else if (starts_with(text, i, "<?") || starts_with(text, i, "<!")) {
            i = skip_past(text, i, ">");
        } else if (starts_with(text, i, "<metadata")) {
            i = skip_past(text, i, "</metadata>");
        } else if (starts_with(text, i, "<script")) {
            i = skip_past(text, i, "</script>");
        } else if (starts_with(text, i, "</")) {
            const std::size_t end = skip_past(text, i, ">");
            out.append(text.substr(i, end - i));
            i = end;
        } else {
            i = parse_tag(text, i, name, attributes, self_closing);
            out += '<' + name;
            if (first_tag)
                out += " id=" + attribute_value(html_escape(prefix)) + " role=\"img\"";
            for (auto& a : attributes) {
                if (first_tag && (a.name == "id" || a.name == "role"))
                    continue;
                Attribute kept = rewrite(std::move(a), prefix);
                if (kept.name.empty())
                    continue;
                out += ' ' + kept.name;
                if (kept.has_value)
                    out += '=' + attribute_value(kept.value);
            }
            out += self_closing ? "/>" : ">";
            if (first_tag && !has_title && !self_closing)
                out += "<title>" + html_escape(title) + "</title>";
            first_tag = false;
        }
    }
    return out;
}

} // namespace mhb
