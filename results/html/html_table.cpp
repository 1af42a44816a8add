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

// The leading columns that name a row, and the columns that say what it means.
bool key_column(const std::string& header) {
    for (const char* key : {"Problem", "Algorithm", "Rank", "Design", "Label", "Condition", "Component"})
        if (header == key)
            return true;
    return false;
}

bool decisive_column(const std::string& header) {
    for (const char* decisive :
         {"Result", "Reading", "p (Holm)", "Signed-rank p (Holm)", "Post-hoc p (Holm)", "vs best", "Verdict"})
        if (header == decisive)
            return true;
    return false;
}

// The label of an algorithm column's cell with a swatch of its figures' colour.
std::string coloured_label(const std::string& text, const std::map<std::string, std::string>& colours) {
    const auto found = colours.find(text);
    if (found == colours.end())
        return html_escape(text);
    return "<span class=\"swatch\" style=\"background:" + html_escape(found->second) + "\"></span>" +
           html_escape(text);
}

std::string cell_html(const TableCell& cell, bool text_column,
                      const std::map<std::string, std::string>* colours = nullptr) {
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
    const std::string text =
        colours != nullptr ? coloured_label(cell.text, *colours) : html_escape(cell.text);
    out += cell.bold && !text.empty() ? "<strong>" + text + "</strong>" : text;
    return out + "</td>";
}

} // namespace

std::vector<std::size_t> html_column_order(const std::vector<std::string>& header) {
    std::vector<std::size_t> order;
    std::size_t keys = 0;
    while (keys < header.size() && key_column(header[keys]))
        order.push_back(keys++);
    for (std::size_t c = keys; c < header.size(); ++c)
        if (decisive_column(header[c]))
            order.push_back(c);
    for (std::size_t c = keys; c < header.size(); ++c)
        if (!decisive_column(header[c]))
            order.push_back(c);
    return order;
}

std::string render_html_table(const Table& table, const std::string& anchor, int heading_level,
                              const std::map<std::string, std::string>& colours) {
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
    const std::vector<std::size_t> order = html_column_order(table.header);
    for (std::size_t c : order)
        out += std::string("<th scope=\"col\"") + (text[c] ? " class=\"l\"" : "") + ">" +
               html_escape(table.header[c]) + "</th>";
    out += "</tr></thead>\n<tbody>\n";
    const auto row_html = [&](const std::vector<TableCell>& row) {
        std::string tr = "<tr>";
        for (std::size_t c : order)
            if (c < row.size())
                tr += cell_html(row[c], text[c],
                                table.header[c] == "Algorithm" || table.header[c] == "Label" ? &colours
                                                                                             : nullptr);
        return tr + "</tr>\n";
    };
    for (const auto& row : table.rows)
        out += row_html(row);
    out += "</tbody>\n";
    if (!table.footer.empty()) { // the w/t/l counts: under the body, never sorted with it
        out += "<tfoot>\n";
        for (const auto& row : table.footer)
            out += row_html(row);
        out += "</tfoot>\n";
    }
    return out + "</table></div>\n</section>\n";
}

} // namespace mhb
