#include "results/html/html_table.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

#include "results/html/html_escape.hpp"

namespace mhb {

namespace {

// Cells longer than this wrap (a "Reading" sentence, a full spec) instead of widening the table.
constexpr std::size_t long_cell = 40;

// Whether `text` starts with a number as the page's sort script reads one (1.5, -2e-05, .3, inf,
// -inf; "20/20" by its 20): such columns are right-aligned, the others left-aligned.
bool starts_with_number(const std::string& text) {
    std::size_t i = text[0] == '+' || text[0] == '-' ? 1 : 0;
    if (text.compare(i, 3, "inf") == 0) // "inf", "inf ..." but not "info"
        return i + 3 == text.size() || std::isalnum(static_cast<unsigned char>(text[i + 3])) == 0;
    if (i < text.size() && text[i] == '.')
        ++i;
    return i < text.size() && text[i] >= '0' && text[i] <= '9';
}

// A column is numeric when each of its defined cells starts with a number (and one does).
std::vector<bool> text_columns(const Table& table) {
    std::vector<bool> text(table.header.size(), false);
    std::vector<bool> any(table.header.size(), false);
    for (const auto& row : table.rows)
        for (std::size_t c = 0; c < row.size() && c < text.size(); ++c) {
            const std::string& t = row[c].text;
            if (t.empty() || t == undefined_text || t == "nan")
                continue;
            any[c] = true;
            if (!starts_with_number(t))
                text[c] = true;
        }
    for (std::size_t c = 0; c < text.size(); ++c)
        text[c] = text[c] || !any[c];
    return text;
}

std::string cell_html(const TableCell& cell, bool text_column) {
    std::string classes;
    if (text_column)
        classes = "l";
    if (cell.text.size() > long_cell)
        classes += classes.empty() ? "long" : " long";
    std::string out = "<td";
    if (!classes.empty())
        out += " class=\"" + classes + "\"";
    if (!cell.value.empty() && cell.value != cell.text)
        out += " data-value=\"" + html_escape(cell.value) + "\"";
    out += '>';
    const std::string text = html_escape(cell.text);
    out += cell.bold && !text.empty() ? "<strong>" + text + "</strong>" : text;
    return out + "</td>";
}

} // namespace

std::string render_html_table(const Table& table, const std::string& anchor, int heading_level) {
    const std::string h = std::to_string(std::clamp(heading_level, 2, 6));
    const std::string caption_id = anchor + "-caption";
    std::string out = "<section class=\"table\" id=\"" + html_escape(anchor) + "\">\n";
    out += "<h" + h + ">" + html_escape(table.title) + "</h" + h + ">\n";
    if (!table.caption.empty())
        out += "<p class=\"caption\" id=\"" + html_escape(caption_id) + "\">" + html_escape(table.caption) +
               "</p>\n";
    out += "<div class=\"scroll\"><table class=\"sortable\"";
    if (!table.caption.empty())
        out += " aria-describedby=\"" + html_escape(caption_id) + "\"";
    out += ">\n<thead><tr>";
    const std::vector<bool> text = text_columns(table);
    for (std::size_t c = 0; c < table.header.size(); ++c)
        out += std::string("<th scope=\"col\"") + (text[c] ? " class=\"l\"" : "") + ">" +
               html_escape(table.header[c]) + "</th>";
    out += "</tr></thead>\n<tbody>\n";
    for (const auto& row : table.rows) {
        out += "<tr>";
        for (std::size_t c = 0; c < row.size(); ++c)
            out += cell_html(row[c], c < text.size() && text[c]);
        out += "</tr>\n";
    }
    out += "</tbody>\n";
    if (!table.footer.empty()) { // the w/t/l counts: under the body, never sorted with it
        out += "<tfoot>\n";
        for (const auto& row : table.footer) {
            out += "<tr>";
            for (std::size_t c = 0; c < row.size(); ++c)
                out += cell_html(row[c], c < text.size() && text[c]);
            out += "</tr>\n";
        }
        out += "</tfoot>\n";
    }
    return out + "</table></div>\n</section>\n";
}

} // namespace mhb
