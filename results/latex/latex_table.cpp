#include "results/latex/latex_table.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <tuple>
#include <utility>

#include "results/latex/latex_numbers.hpp"
#include "results/latex/latex_text.hpp"
#include "results/table_model/table.hpp"

namespace mhb {

namespace {

constexpr double page_width = 345.0;  // \textwidth of a one-column article, 10 pt, default geometry
constexpr double ieee_column = 252.0; // \columnwidth of a two-column IEEE paper
constexpr double column_sep = 4.0;    // \tabcolsep of every table...
constexpr double tight_sep = 3.0;     // ...but one that fits in one part with this and not with that
constexpr double usable = 0.96 * page_width;
constexpr double wrap_above = 120.0;     // a text column wider than this wraps
constexpr double narrowest_wrap = 40.0;  // a spec or label: it breaks after ',' and ':'
constexpr double narrowest_prose = 90.0; // a sentence narrower than this reads badly
// Heights, measured with pdflatex (tests/latex/ checks real reports against the page). The text
// height of a one-column article, 10 pt, default geometry, is the smallest of the targets (IEEEtran
// conference 672 pt, elsarticle 5p 682 pt); 96 % of it is used, as of the width.
constexpr double page_height = 550.0;
constexpr double usable_height = 0.96 * page_height;
constexpr double row_height = 9.8;   // a \footnotesize row (9.75 pt; 9.79 with exponents and \boldmath)
constexpr double rules_height = 8.6; // \toprule, \midrule and \bottomrule with their spacing
constexpr double heading_height = row_height + 4.5; // a heading line and the \addlinespace above it
constexpr double footer_rule = 7.0;                 // the \midrule above the w/t/l rows
constexpr double caption_base = 23.0;               // IEEEtran's "TABLE I" line and the skips (article: 7 pt)
constexpr double caption_line = 12.0;  // a line of caption (\normalsize in article; 9 pt in IEEEtran)
constexpr double caption_scale = 1.25; // \normalsize against the \footnotesize widths are estimated at
constexpr double notes_skip = 6.0;     // \medskip above the notes
constexpr double notes_line = 9.5;     // a line of notes (\footnotesize)
constexpr double ragged = 1.1;         // ragged-right lines end short of the width
constexpr double space = 2.67;
constexpr double marker_width = 6.61;

struct Cell {
    std::string latex;
    double width = 0.0;
    std::string below; // the spread's line (Table::latex_spread_below)
    double below_width = 0.0;
    bool empty = true;
    // "no successful run" in a column of numbers: it may span the empty cells after it.
    bool text_in_numbers = false;
};

struct Column {
    std::size_t index = 0;
    LatexColumn style;
    bool numeric = false;
    std::vector<std::string> header_lines;
    double natural = 0.0; // on one line
    double least = 0.0;   // wrapped as far as it goes
    bool wrap = false;
    double width = 0.0; // of a wrapped column, once laid out
};

struct Part {
    std::vector<std::size_t> columns; // positions in the kept columns
    std::string name;
    bool resize = false;
};

bool blank(const TableCell& cell) {
    return !cell.number && cell.text.empty();
}

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

std::string text_latex(const TableCell& cell, const LatexColumn& style) {
    if (!cell.latex.empty())
        return cell.latex;
    return style.prose ? latex_prose(cell.text) : latex_spec_text(cell.text);
}

Cell render_cell(const TableCell& cell, const ColumnFormats& formats, const LatexColumn& style, bool numeric,
                 bool markers, bool spread_below) {
    Cell out;
    out.empty = blank(cell);
    if (!cell.number) {
        out.latex = text_latex(cell, style);
        out.width = latex_text_width(out.latex);
        out.text_in_numbers = numeric && !out.empty;
        if (cell.bold && !out.latex.empty()) {
            out.latex = "\\textbf{" + out.latex + "}";
            out.width *= 1.1;
        }
        return out;
    }
    const LatexNumber number = latex_number(*cell.number, formats.numbers.at(cell.group));
    out.latex = number.math();
    out.width = number.width;
    if (cell.spread) {
        const LatexNumber spread = latex_number(*cell.spread, formats.spreads.at(cell.group));
        const std::string pad = spread.pad.empty() ? "" : "$" + spread.pad + "$";
        const bool percent = cell.spread_style == SpreadStyle::slash_percent;
        if (spread_below) {
            out.below = percent ? "$" + spread.body + "$\\%" + pad : "($" + spread.body + "$)" + pad;
            out.below_width = (percent ? 7.08 : 6.61) + spread.width;
        } else if (percent) {
            out.latex += "~/~$" + spread.body + "$\\%" + pad;
            out.width += 2 * space + 4.25 + 7.08 + spread.width;
        } else {
            out.latex += "~($" + spread.body + "$)" + pad;
            out.width += space + 6.61 + spread.width;
        }
    }
    if (markers) {
        // Every cell of a column with markers keeps a marker's room, so the numbers still line up.
        out.latex += cell.marker.empty() ? "~\\phantom{$+$}" : "~$" + cell.marker + "$";
        out.width += space + marker_width;
        if (!out.below.empty()) {
            out.below += "\\phantom{~$+$}";
            out.below_width += space + marker_width;
        }
    }
    if (cell.bold) { // \boldmath bolds the numbers set in maths
        out.latex = "{\\boldmath " + out.latex + "}";
        out.width *= 1.12;
    }
    return out;
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

// Text split where a line of `width` ends: at the last break (a space, \allowbreak) that fits.
std::pair<std::string, std::string> first_line(const std::string& latex, double width) {
    static const std::string allow = "\\allowbreak{}";
    if (latex_text_width(latex) <= width)
        return {latex, ""};
    std::size_t best = std::string::npos;
    for (std::size_t i = 0; i < latex.size(); ++i) {
        const bool blank_space = latex[i] == ' ';
        if (!blank_space && latex.compare(i, allow.size(), allow) != 0)
            continue;
        if (latex_text_width(latex.substr(0, i)) > width)
            break;
        best = i;
    }
    if (best == std::string::npos)
        return {latex, ""};
    const std::size_t rest = best + (latex[best] == ' ' ? 1 : allow.size());
    return {latex.substr(0, best), latex.substr(rest)};
}

double cost(const std::vector<Column>& columns, const std::vector<std::size_t>& which,
            double sep = column_sep) {
    double total = 0.0;
    for (std::size_t k : which)
        total += columns[k].least + 2 * sep;
    return total;
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

// "Table 2: Fitness ..." -> "Fitness ..."; " [budget X]" goes too when the caption says "Budget: X.".
std::string caption_title(const Table& table) {
    std::string title = table.title;
    if (title.rfind("Table ", 0) == 0) {
        std::size_t i = 6;
        while (i < title.size() && title[i] >= '0' && title[i] <= '9')
            ++i;
        if (i > 6 && title.compare(i, 2, ": ") == 0)
            title.erase(0, i + 2);
    }
    const std::size_t budget = title.rfind(" [budget ");
    if (budget != std::string::npos && title.back() == ']') {
        const std::string value = title.substr(budget + 9, title.size() - budget - 10);
        if (table.caption.find("Budget: " + value + ".") != std::string::npos)
            title.erase(budget);
    }
    return title;
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
    std::string out;
    for (const auto& item : items)
        out += (out.empty() ? "" : separator) + item;
    return out;
}

// The rows of a table part and the room a float has for them, in pt.
struct Heights {
    std::vector<double> rows;      // each body row: a line, two with the spread below, more if wrapped
    std::vector<bool> group_start; // a heading line goes above the row (a run of rows begins)
    double heading = 0.0;          // a heading line, when the table has headings
    double footer = 0.0;           // the w/t/l rows under the body, in the last float
    double first_room = 0.0;       // a float with the caption, the header and the notes
    double later_room = 0.0;       // a continued float: the caption and header, no notes
};

// Rows [first, second) of each float, each fitting its room at `scale`: runs of rows stay
// together where the float would still be at least half full, a float's first row is headed (the
// heading repeats when a run continues), a heading never ends a float (it goes with its first
// row), and the footer goes with the last row.
std::vector<std::pair<std::size_t, std::size_t>> pack_rows(const Heights& heights, double scale) {
    const std::size_t n = heights.rows.size();
    std::vector<std::pair<std::size_t, std::size_t>> out;
    for (std::size_t start = 0; start < n;) {
        const double room = scale * (out.empty() ? heights.first_room : heights.later_room);
        double used = 0.0;
        double used_at_boundary = 0.0;
        std::size_t end = start;
        std::size_t boundary = start; // the last end at which a run of rows ends
        for (std::size_t r = start; r < n; ++r) {
            double h = heights.rows[r] + (r == start || heights.group_start[r] ? heights.heading : 0.0);
            if (r + 1 == n)
                h += heights.footer;
            if (r > start && used + h > room)
                break;
            used += h;
            end = r + 1;
            if (end == n || heights.group_start[end]) {
                boundary = end;
                used_at_boundary = used;
            }
        }
        if (end < n && boundary > start) {
            std::size_t run_begin = end - 1; // the run the float would end inside
            while (run_begin > start && !heights.group_start[run_begin])
                --run_begin;
            // A run cut short leaves at least two rows above the cut.
            if (used_at_boundary >= 0.5 * room || end - run_begin < 2)
                end = boundary;
        }
        out.emplace_back(start, end);
        start = end;
    }
    if (out.empty())
        out.emplace_back(0, 0);
    return out;
}

// As few floats as fit, as evenly filled as they can be: the smallest room that needs no more
// floats than the full room does.
std::vector<std::pair<std::size_t, std::size_t>> split_rows(const Heights& heights) {
    auto best = pack_rows(heights, 1.0);
    if (best.size() < 2)
        return best;
    double low = 0.0;
    double high = 1.0;
    for (int i = 0; i < 30; ++i) {
        const double mid = (low + high) / 2;
        if (auto chunks = pack_rows(heights, mid); chunks.size() <= best.size()) {
            high = mid;
            best = std::move(chunks);
        } else {
            low = mid;
        }
    }
    return best;
}

} // namespace

std::string render_latex(const Table& table) {
    const std::size_t n = table.header.size();
    std::vector<LatexColumn> styles = table.latex;
    if (styles.size() != n) {
        styles.assign(n, LatexColumn{});
        if (n > 0)
            styles.front().key = true;
    }
    const std::vector<ColumnFormats> formats = column_formats(table);

    // 1. What stays a column, and what the notes say instead.
    std::vector<std::string> folded;
    std::vector<std::string> without_values;
    std::vector<Column> columns;
    std::optional<std::size_t> heading; // the column whose values head runs of rows instead
    for (std::size_t c = 0; c < n; ++c) {
        const bool all_blank =
            std::all_of(table.rows.begin(), table.rows.end(), [&](const auto& row) { return blank(row[c]); });
        const bool numeric = is_numeric(table, c);
        // Constant: every row that has a value has the same (the reference's row may have none).
        const TableCell* first = nullptr;
        bool constant = styles[c].fold_constant;
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
        constant = constant && first != nullptr;
        const std::string name =
            styles[c].header.empty() ? latex_prose(table.header[c]) : flat(styles[c].header);
        if (all_blank && !table.rows.empty()) {
            without_values.push_back(name);
            continue;
        }
        if (constant) {
            const std::string value =
                numeric ? "$" + latex_number(*first->number, formats[c].numbers.at(first->group)).body + "$"
                        : text_latex(*first, styles[c]);
            folded.push_back(name + ": " + value + ".");
            continue;
        }
        if (styles[c].heading && !numeric && !heading) {
            heading = c;
            continue;
        }
        Column column;
        column.index = c;
        column.style = styles[c];
        column.numeric = numeric;
        columns.push_back(std::move(column));
    }
    if (columns.empty()) { // nothing varies: keep the first column rather than no table
        Column column;
        column.style = styles.front();
        columns.push_back(std::move(column));
        if (!folded.empty())
            folded.erase(folded.begin());
    }

    // 2. Every cell in LaTeX, and the widths the columns need.
    std::vector<bool> markers;
    for (const auto& column : columns)
        markers.push_back(has_marker(table, column.index));
    const auto render_rows = [&](const std::vector<std::vector<TableCell>>& rows) {
        std::vector<std::vector<Cell>> out;
        for (const auto& row : rows) {
            auto& cells = out.emplace_back();
            for (std::size_t k = 0; k < columns.size(); ++k)
                cells.push_back(render_cell(row[columns[k].index], formats[columns[k].index],
                                            columns[k].style, columns[k].numeric, markers[k],
                                            table.latex_spread_below));
        }
        return out;
    };
    const auto body = render_rows(table.rows);
    const auto footer = render_rows(table.footer);
    for (std::size_t k = 0; k < columns.size(); ++k) {
        Column& column = columns[k];
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
                ? std::min(column.natural, std::max({piece, header_piece,
                                                     column.style.prose ? narrowest_prose : narrowest_wrap}))
                : column.natural;
    }

    // 3. The parts: one table if it fits, else the key columns and as many groups as fit.
    std::vector<std::size_t> everything(columns.size());
    std::iota(everything.begin(), everything.end(), 0);
    std::vector<Part> parts;
    double sep = column_sep;
    if (cost(columns, everything) > usable && cost(columns, everything, tight_sep) <= usable)
        sep = tight_sep;
    if (cost(columns, everything, sep) <= usable) {
        parts.push_back({everything, "", false});
    } else {
        std::vector<std::size_t> keys;
        std::vector<std::vector<std::size_t>> groups;
        for (std::size_t k = 0; k < columns.size(); ++k) {
            if (columns[k].style.key) {
                keys.push_back(k);
                continue;
            }
            if (groups.empty() || columns[groups.back().back()].style.group != columns[k].style.group ||
                columns[k].style.group.empty())
                groups.emplace_back();
            groups.back().push_back(k);
        }
        std::vector<std::size_t> current;
        const auto with = [&](const std::vector<std::size_t>& more) {
            std::vector<std::size_t> all = keys;
            all.insert(all.end(), current.begin(), current.end());
            all.insert(all.end(), more.begin(), more.end());
            return all;
        };
        const auto close = [&] {
            if (current.empty())
                return;
            std::vector<std::size_t> all = with({}); // the keys first, then the part's own columns
            parts.push_back({all, "", cost(columns, all) > usable});
            current.clear();
        };
        for (const auto& group : groups) {
            if (cost(columns, with(group)) <= usable) {
                current.insert(current.end(), group.begin(), group.end());
                continue;
            }
            close();
            if (cost(columns, with(group)) <= usable) {
                current = group;
                continue;
            }
            for (std::size_t k : group) { // a group too wide on its own: column by column
                if (!current.empty() && cost(columns, with({k})) > usable)
                    close();
                current.push_back(k);
            }
        }
        close();
        if (parts.empty())
            parts.push_back({everything, "", true});
        for (auto& part : parts) {
            std::vector<std::string> names;
            for (std::size_t k : part.columns) {
                const std::string& g = columns[k].style.group;
                if (!columns[k].style.key && !g.empty() &&
                    std::find(names.begin(), names.end(), g) == names.end())
                    names.push_back(g);
            }
            part.name = join(names, ", ");
        }
    }

    // 4. Each part as table environments: one, or several floats of consecutive rows when the
    // part is taller than a page.
    const std::string title = latex_escape(caption_title(table));
    std::string notes = join(folded, " ");
    if (!without_values.empty())
        notes += std::string(notes.empty() ? "" : " ") +
                 "Columns without any value (left out): " + join(without_values, ", ") + ".";
    if (!table.caption.empty())
        notes += (notes.empty() ? "" : " ") + latex_prose(table.caption);
    const std::string sep_text = sep == column_sep ? "4pt" : "3pt";
    // Footer rows (the w/t/l counts) appear in the parts that hold some of their counts; their
    // label, in the first column, moves to the part's first cell when that column is gone.
    const bool label_kept = columns.front().index == 0 || heading == std::size_t{0};
    std::string out;
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const Part& part = parts[p];
        // Wrapped columns share what the others leave, up to their width on one line.
        double fixed = 0.0;
        double slack = 0.0;
        for (std::size_t k : part.columns) {
            fixed += columns[k].least + 2 * sep;
            if (columns[k].wrap)
                slack += columns[k].natural - columns[k].least;
        }
        const double spare = std::max(0.0, usable - fixed);
        double width = 0.0;
        std::string spec;
        for (std::size_t k : part.columns) {
            Column& column = columns[k];
            if (column.wrap) {
                const double share = slack > 0.0 ? std::min(1.0, spare / slack) : 0.0;
                column.width = std::ceil(column.least + share * (column.natural - column.least));
                spec += ">{\\raggedright\\arraybackslash}p{" +
                        std::to_string(static_cast<int>(column.width)) + "pt}";
                width += column.width;
            } else {
                spec += column.numeric ? "r" : "l";
                width += column.natural;
            }
            width += 2 * sep;
        }
        const bool wide = width > ieee_column;
        std::string caption = title;
        if (parts.size() > 1)
            caption += " (" + std::string(part.name.empty() ? "" : latex_escape(part.name) + "; ") + "part " +
                       std::to_string(p + 1) + " of " + std::to_string(parts.size()) + ")";
        const std::string label = "tab:" + table.id + (p == 0 ? "" : "-" + std::to_string(p + 1));
        const std::string part_notes = p == 0 ? notes : "Notes as for Table~\\ref{tab:" + table.id + "}.";

        // 5. The height of what the part holds, in pt, to split its rows into floats that fit a page.
        const auto footer_shown = [&](const std::vector<Cell>& row) {
            return std::any_of(part.columns.begin(), part.columns.end(),
                               [&](std::size_t k) { return !columns[k].style.key && !row[k].empty; });
        };
        Heights heights;
        for (std::size_t r = 0; r < body.size(); ++r) {
            std::size_t row_lines = 1;
            for (std::size_t k : part.columns) {
                if (!body[r][k].below.empty())
                    row_lines = std::max<std::size_t>(row_lines, 2);
                if (columns[k].wrap && columns[k].width > 0.0)
                    row_lines = std::max(
                        row_lines, static_cast<std::size_t>(std::ceil(body[r][k].width / columns[k].width)));
            }
            heights.rows.push_back(static_cast<double>(row_lines) * row_height);
            heights.group_start.push_back(
                heading && (r == 0 || table.rows[r][*heading].text != table.rows[r - 1][*heading].text));
        }
        heights.heading = heading ? heading_height : 0.0;
        const auto footer_rows = std::count_if(footer.begin(), footer.end(), footer_shown);
        if (footer_rows > 0) // a footer's label may head its row (below): counted as a heading
            heights.footer = footer_rule + static_cast<double>(footer_rows) *
                                               (label_kept || heading ? row_height : heading_height);
        std::size_t head_lines = 1;
        for (std::size_t k : part.columns) {
            const Column& column = columns[k];
            std::size_t lines = column.header_lines.size();
            if (column.wrap && column.width > 0.0)
                lines =
                    static_cast<std::size_t>(std::ceil(latex_text_width(header_cell(column)) / column.width));
            head_lines = std::max(head_lines, lines);
        }
        const double float_width = wide ? page_width : ieee_column; // the narrowest text it wraps in
        const auto lines_of = [](double text_width, double line) {
            return std::max(1.0, std::ceil(text_width / line));
        };
        const auto frame = [&](const std::string& text) { // caption, header and rules
            return caption_base +
                   caption_line * lines_of(caption_scale * latex_text_width(text), float_width) +
                   rules_height + static_cast<double>(head_lines) * row_height;
        };
        const double notes_room =
            part_notes.empty()
                ? 0.0
                : notes_skip + notes_line * lines_of(ragged * latex_text_width(part_notes), float_width);
        heights.first_room = usable_height - frame(caption) - notes_room;
        heights.later_room = usable_height - frame(caption + " (continued)");
        const std::vector<std::pair<std::size_t, std::size_t>> chunks = split_rows(heights);

        std::string header_row;
        for (std::size_t i = 0; i < part.columns.size(); ++i)
            header_row += (i == 0 ? "" : " & ") + header_cell(columns[part.columns[i]]);
        header_row += " \\\\\n";
        const auto write_rows = [&](const std::vector<std::vector<Cell>>& rows, bool is_footer,
                                    std::size_t begin, std::size_t end) {
            std::string text;
            const auto& source = is_footer ? table.footer : table.rows;
            const std::string* previous = nullptr; // a float's first row is headed, even inside a run
            for (std::size_t r = begin; r < end; ++r) {
                const auto& row = rows[r];
                if (is_footer && !footer_shown(row))
                    continue;
                // The column that heads rows: a heading; a footer's label whose column is gone and
                // whose row has no empty first cell to take it: a heading too.
                const std::optional<std::size_t> heads =
                    heading ? heading
                            : (is_footer && !label_kept && !row[part.columns.front()].empty
                                   ? std::optional<std::size_t>(0)
                                   : std::nullopt);
                if (heads && (previous == nullptr || *previous != source[r][*heads].text)) {
                    previous = &source[r][*heads].text;
                    if (!text.empty())
                        text += "\\addlinespace\n";
                    text += "\\multicolumn{" + std::to_string(part.columns.size()) + "}{l}{\\textit{" +
                            text_latex(source[r][*heads], styles[*heads]) + "}} \\\\\n";
                }
                std::string below;
                bool any_below = false;
                for (std::size_t i = 0; i < part.columns.size(); ++i) {
                    const std::size_t k = part.columns[i];
                    Cell cell = row[k];
                    if (is_footer && i == 0 && !label_kept && cell.empty)
                        cell.latex = latex_spec_text(table.footer[r].front().text);
                    // Wrapped text beside numbers with a spread's line: its second line goes there.
                    const bool has_below = std::any_of(part.columns.begin(), part.columns.end(),
                                                       [&](std::size_t j) { return !row[j].below.empty(); });
                    if (columns[k].wrap && has_below && !columns[k].numeric && cell.below.empty())
                        std::tie(cell.latex, cell.below) = first_line(cell.latex, columns[k].width);
                    const std::string separator = i == 0 ? "" : " & ";
                    below += separator + cell.below;
                    any_below = any_below || !cell.below.empty();
                    std::size_t span = 1;
                    if (cell.text_in_numbers && !is_footer)
                        while (i + span < part.columns.size() && part.columns[i + span] == k + span &&
                               row[k + span].empty)
                            ++span;
                    if (span > 1) {
                        text +=
                            separator + "\\multicolumn{" + std::to_string(span) + "}{l}{" + cell.latex + "}";
                        for (std::size_t s = 1; s < span; ++s)
                            below += " & ";
                        i += span - 1;
                    } else {
                        text += separator + cell.latex;
                    }
                }
                text += " \\\\\n";
                if (any_below)
                    text += below + " \\\\\n";
            }
            return text;
        };

        const std::string environment = wide ? "table*" : "table";
        for (std::size_t c = 0; c < chunks.size(); ++c) {
            std::string rows_text = write_rows(body, false, chunks[c].first, chunks[c].second);
            if (c + 1 == chunks.size())
                if (const std::string summary = write_rows(footer, true, 0, footer.size()); !summary.empty())
                    rows_text += "\\midrule\n" + summary;
            std::string parts_said;
            if (parts.size() > 1)
                parts_said += "; part " + std::to_string(p + 1) + " of " + std::to_string(parts.size());
            if (chunks.size() > 1)
                parts_said += "; rows " + std::to_string(chunks[c].first + 1) + "-" +
                              std::to_string(chunks[c].second) + " of " + std::to_string(body.size());
            out += "% " + table.title + " (written by mhbench report)" + parts_said + "\n";
            out +=
                "% Needs \\usepackage{booktabs,array" + std::string(part.resize ? ",graphicx" : "") + "}.\n";
            if (wide)
                out += "% table*: wider than one column of a two-column paper (252 pt), so it spans both "
                       "there; in one column it is a plain table.\n";
            if (c == 0 && chunks.size() > 1)
                out += "% Too tall for one page: its rows continue in the next " +
                       std::string(chunks.size() == 2 ? "float"
                                                      : std::to_string(chunks.size() - 1) + " floats") +
                       ", under the same number.\n";
            out += "\\begin{" + environment + "}[htbp]\n\\centering\n";
            if (c == 0)
                out += "\\caption{" + caption + "}\n\\label{" + label + "}\n";
            else
                out += "\\addtocounter{table}{-1}\n\\caption{" + caption + " (continued)}\n";
            out += "\\footnotesize\n\\setlength{\\tabcolsep}{" + sep_text + "}\n";
            if (part.resize)
                out += "% \\resizebox: one column alone is wider than the "
                       "page.\n\\resizebox{\\linewidth}{!}{%\n";
            out += "\\begin{tabular}{" + spec + "}\n\\toprule\n" + header_row + "\\midrule\n" + rows_text +
                   "\\bottomrule\n\\end{tabular}" + (part.resize ? "}" : "") + "\n";
            if (c == 0 && !part_notes.empty())
                out += "\\par\\medskip\n{\\raggedright " + part_notes + "\\par}\n";
            out += "\\end{" + environment + "}\n";
        }
    }
    return out;
}

} // namespace mhb
