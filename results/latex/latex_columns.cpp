// Steps 1 and 2 of a LaTeX table's layout (latex_table.hpp): which columns stay columns, and what
// the notes say instead (a constant column, a column without any value) or a heading line (a
// LatexColumn::heading column); then every kept cell in LaTeX, each column's header lines and the
// widths it needs on one line and wrapped as far as it goes.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "results/latex/latex_layout.hpp"
#include "results/latex/latex_numbers.hpp"
#include "results/latex/latex_text.hpp"

namespace mhb::latex_detail {

namespace {

constexpr double wrap_above = 120.0;     // a text column wider than this wraps
constexpr double narrowest_wrap = 40.0;  // a spec or label: it breaks after ',' and ':'
constexpr double narrowest_prose = 90.0; // a sentence narrower than this reads badly

bool is_numeric(const Table& table, std::size_t column) {
    for (const auto& row : table.rows)
        if (row[column].number)
            return true;
    return false;
}

bool has_marker(const Table& table, std::size_t column) {
    for (const auto* rows : {&table.rows, &table.footer})
        for (const auto& row : *rows)
            if (!row[column].marker.empty())
                return true;
    return false;
}

// The header of a column on as few lines as its content's width allows (a long header over short
// numbers takes two or three lines). Words joined by " - " stay together ("f - f*").
std::vector<std::string> header_lines(const std::string& header, const LatexColumn& style, double content) {
    if (!style.header.empty()) {
        std::vector<std::string> lines;
        std::size_t start = 0;
        for (std::size_t at; (at = style.header.find("\\\\", start)) != std::string::npos; start = at + 2)
            lines.push_back(style.header.substr(start, at - start));
        lines.push_back(style.header.substr(start));
        return lines;
    }
    std::vector<std::string> words;
    for (std::size_t start = 0; start < header.size();) {
        const std::size_t end = std::min(header.find(' ', start), header.size());
        std::string word = header.substr(start, end - start);
        if (!words.empty() && (word == "-" || (words.back().size() >= 2 &&
                                               words.back().substr(words.back().size() - 2) == " -")))
            words.back() += " " + word;
        else if (!word.empty())
            words.push_back(word);
        start = end + 1;
    }
    double widest_word = 0.0;
    for (const auto& w : words)
        widest_word = std::max(widest_word, latex_text_width(latex_prose(w)));
    const double target = std::max({content, widest_word, 24.0});
    std::vector<std::string> lines;
    for (const auto& w : words) {
        if (!lines.empty() && latex_text_width(latex_prose(lines.back() + " " + w)) <= target)
            lines.back() += " " + w;
        else
            lines.push_back(w);
    }
    if (lines.size() > 3) // more lines than a header should have: let it be wide instead
        return {latex_prose(header)};
    for (auto& line : lines)
        line = latex_prose(line);
    return lines;
}

// A header as one line of text for the notes: "Signed-\\rank $p$" -> "Signed-rank $p$".
std::string flat(const std::string& header) {
    std::string out;
    std::size_t start = 0;
    for (std::size_t at; (at = header.find("\\\\", start)) != std::string::npos; start = at + 2) {
        out += header.substr(start, at - start);
        if (!out.empty() && out.back() != '-')
            out += ' ';
    }
    return out + header.substr(start);
}

// The value of a column to fold into the notes, or nullptr. Constant: every row that has a value has
// the same (the reference's row may have none); a number without a spread or a marker.
const TableCell* constant_value(const Table& table, std::size_t c, bool fold_constant, bool numeric) {
    const TableCell* first = nullptr;
    bool constant = fold_constant;
    for (const auto& row : table.rows) {
        const TableCell& cell = row[c];
        if (blank(cell) || !constant)
            continue;
        if (first == nullptr) {
            first = &cell;
            constant = !numeric || (cell.number && !cell.spread && cell.marker.empty());
            continue;
        }
        constant = numeric ? cell.number && !cell.spread && cell.marker.empty() &&
                                 (*cell.number == *first->number ||
                                  (std::isnan(*cell.number) && std::isnan(*first->number)))
                           : cell.text == first->text;
    }
    return constant ? first : nullptr;
}

// The value of a folded column as the notes say it.
std::string folded_value(const TableCell& cell, const ColumnFormats& formats, const LatexColumn& style,
                         bool numeric) {
    if (!numeric)
        return text_latex(cell, style);
    // Appended, not "$" + body: GCC 12 sees a false overlap (-Wrestrict) in that.
    std::string math = "$";
    math += latex_number(*cell.number, formats.numbers.at(cell.group)).body;
    return math + "$";
}

// 1. What stays a column, and what the notes say instead.
void choose_columns(const Table& table, const std::vector<ColumnFormats>& formats, TableLayout& layout) {
    const std::vector<LatexColumn>& styles = layout.styles;
    for (std::size_t c = 0; c < table.header.size(); ++c) {
        const bool all_blank =
            std::all_of(table.rows.begin(), table.rows.end(), [&](const auto& row) { return blank(row[c]); });
        const bool numeric = is_numeric(table, c);
        const TableCell* constant = constant_value(table, c, styles[c].fold_constant, numeric);
        const std::string name =
            styles[c].header.empty() ? latex_prose(table.header[c]) : flat(styles[c].header);
        if (all_blank && !table.rows.empty()) {
            layout.without_values.push_back(name);
            continue;
        }
        if (constant != nullptr) {
            layout.folded.push_back(name + ": " + folded_value(*constant, formats[c], styles[c], numeric) +
                                    ".");
            continue;
        }
        if (styles[c].heading && !numeric && !layout.heading) {
            layout.heading = c;
            continue;
        }
        Column column;
        column.index = c;
        column.style = styles[c];
        column.numeric = numeric;
        layout.columns.push_back(std::move(column));
    }
    if (layout.columns.empty()) { // nothing varies: keep the first column rather than no table
        Column column;
        column.style = styles.front();
        layout.columns.push_back(std::move(column));
        if (!layout.folded.empty())
            layout.folded.erase(layout.folded.begin());
    }
}

// 2. Every kept cell in LaTeX.
std::vector<std::vector<Cell>> render_rows(const Table& table, const std::vector<ColumnFormats>& formats,
                                           const std::vector<Column>& columns,
                                           const std::vector<bool>& markers,
                                           const std::vector<std::vector<TableCell>>& rows) {
    std::vector<std::vector<Cell>> out;
    for (const auto& row : rows) {
        auto& cells = out.emplace_back();
        for (std::size_t k = 0; k < columns.size(); ++k)
            cells.push_back(render_cell(row[columns[k].index], formats[columns[k].index], columns[k].style,
                                        columns[k].numeric, markers[k], table.latex_spread_below));
    }
    return out;
}

// 2. The header lines of kept column k and the widths it needs: on one line, and wrapped.
void measure_column(const Table& table, const std::vector<std::vector<Cell>>& body,
                    const std::vector<std::vector<Cell>>& footer, std::size_t k, Column& column) {
    double content = 0.0;
    double piece = 0.0;
    for (const auto* rows : {&body, &footer})
        for (const auto& row : *rows) {
            const Cell& cell = row[k];
            // Text among numbers spills over the empty cells after it, if any.
            if (cell.text_in_numbers && k + 1 < row.size() && row[k + 1].empty)
                continue;
            content = std::max({content, cell.width, cell.below_width});
            piece = std::max(piece, latex_longest_piece(cell.latex));
        }
    column.header_lines = header_lines(table.header[column.index], column.style, content);
    double header = 0.0;
    double header_piece = 0.0;
    for (const auto& line : column.header_lines) {
        header = std::max(header, latex_text_width(line));
        header_piece = std::max(header_piece, latex_longest_piece(line));
    }
    column.natural = std::max(content, header);
    column.wrap = !column.numeric && (column.style.wrap || column.natural > wrap_above);
    column.least =
        column.wrap
            ? std::min(column.natural,
                       std::max({piece, header_piece, column.style.prose ? narrowest_prose : narrowest_wrap}))
            : column.natural;
}

} // namespace

TableLayout lay_out_columns(const Table& table) {
    TableLayout layout;
    const std::size_t n = table.header.size();
    layout.styles = table.latex;
    if (layout.styles.size() != n) {
        layout.styles.assign(n, LatexColumn{});
        if (n > 0)
            layout.styles.front().key = true;
    }
    const std::vector<ColumnFormats> formats = column_formats(table);
    choose_columns(table, formats, layout);
    layout.footer_label_kept = layout.columns.front().index == 0 || layout.heading == std::size_t{0};

    std::vector<bool> markers;
    for (const auto& column : layout.columns)
        markers.push_back(has_marker(table, column.index));
    layout.body = render_rows(table, formats, layout.columns, markers, table.rows);
    layout.footer = render_rows(table, formats, layout.columns, markers, table.footer);
    for (std::size_t k = 0; k < layout.columns.size(); ++k)
        measure_column(table, layout.body, layout.footer, k, layout.columns[k]);
    return layout;
}

std::string header_cell(const Column& column) {
    if (column.header_lines.size() == 1 || column.wrap) // a paragraph column wraps it itself
        return std::accumulate(column.header_lines.begin(), column.header_lines.end(), std::string(),
                               [](const std::string& a, const std::string& b) {
                                   return a.empty() ? b : a + (a.back() == '-' ? "" : " ") + b;
                               });
    std::string out = std::string("\\begin{tabular}[b]{@{}") + (column.numeric ? "r" : "l") + "@{}}";
    for (std::size_t i = 0; i < column.header_lines.size(); ++i)
        out += (i == 0 ? "" : "\\\\") + column.header_lines[i];
    return out + "\\end{tabular}";
}

} // namespace mhb::latex_detail
