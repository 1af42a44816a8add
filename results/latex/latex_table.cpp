// render_latex, the entry point: a table's layout (latex_layout.hpp: the columns, the parts, the
// floats of each part) written as LaTeX, each float with its comments, caption, label, header, rows
// and notes.
#include "results/latex/latex_table.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "results/latex/latex_layout.hpp"
#include "results/latex/latex_text.hpp"
#include "results/table_model/table.hpp" // a renderer sees tables, never runs

// The helpers live in latex_detail beside the layout steps they read (not behind a using-directive,
// which a unity build would carry into the next source of its batch).
namespace mhb::latex_detail {
namespace {

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

// The notes under the first float of a table: the folded columns, the columns without any value,
// the Markdown caption.
// A table with a short note says it alone: the columns left out empty are no news to a reader of
// the paper, and the method text is in methods.tex.
std::string table_notes(const Table& table, const TableLayout& layout) {
    std::string notes = join(layout.folded, " ");
    if (!layout.without_values.empty() && table.latex_note.empty())
        notes += std::string(notes.empty() ? "" : " ") +
                 "Columns without any value (left out): " + join(layout.without_values, ", ") + ".";
    const std::string& said = table.latex_note.empty() ? table.caption : table.latex_note;
    if (!said.empty()) {
        if (!notes.empty())
            notes += ' ';
        notes += latex_prose(said);
    }
    return notes;
}

// A run of rows begins: the line above it with the value of the column that heads it.
std::string heading_line(const Part& part, const std::string& value) {
    return "\\multicolumn{" + std::to_string(part.columns.size()) + "}{l}{\\textit{" + value + "}} \\\\\n";
}

// Row `r` of the body or the footer: its line, and a line below when a cell has one.
std::string row_lines(const Table& table, const TableLayout& layout, const Part& part,
                      const std::vector<Cell>& row, bool is_footer, std::size_t r) {
    std::string text;
    std::string below;
    bool any_below = false;
    const auto& columns = layout.columns;
    // Wrapped text beside numbers with a spread's line: its second line goes there.
    const bool has_below = std::any_of(part.columns.begin(), part.columns.end(),
                                       [&](std::size_t j) { return !row[j].below.empty(); });
    for (std::size_t i = 0; i < part.columns.size(); ++i) {
        const std::size_t k = part.columns[i];
        Cell cell = row[k];
        if (is_footer && i == 0 && !layout.footer_label_kept && cell.empty)
            cell.latex = latex_spec_text(table.footer[r].front().text);
        if (columns[k].wrap && has_below && !columns[k].numeric && cell.below.empty())
            std::tie(cell.latex, cell.below) = first_line(cell.latex, part.wrap_width[k]);
        const std::string separator = i == 0 ? "" : " & ";
        below += separator + cell.below;
        any_below = any_below || !cell.below.empty();
        std::size_t span = 1;
        if (cell.text_in_numbers && !is_footer)
            while (i + span < part.columns.size() && part.columns[i + span] == k + span &&
                   row[k + span].empty)
                ++span;
        if (span > 1) {
            text += separator + "\\multicolumn{" + std::to_string(span) + "}{l}{" + cell.latex + "}";
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
    return text;
}

// Rows [begin, end) of the body, or the footer rows the part shows, each run of rows under its
// heading line.
std::string rows_text(const Table& table, const TableLayout& layout, const Part& part, bool is_footer,
                      std::size_t begin, std::size_t end) {
    std::string text;
    const auto& rows = is_footer ? layout.footer : layout.body;
    const auto& source = is_footer ? table.footer : table.rows;
    const std::string* previous = nullptr; // a float's first row is headed, even inside a run
    for (std::size_t r = begin; r < end; ++r) {
        const auto& row = rows[r];
        if (is_footer && !footer_row_shown(layout, part, row))
            continue;
        // The column that heads rows: a heading; a footer's label whose column is gone and whose
        // row has no empty first cell to take it: a heading too.
        const std::optional<std::size_t> heads =
            layout.heading ? layout.heading
                           : (is_footer && !layout.footer_label_kept && !row[part.columns.front()].empty
                                  ? std::optional<std::size_t>(0)
                                  : std::nullopt);
        if (heads && (previous == nullptr || *previous != source[r][*heads].text)) {
            previous = &source[r][*heads].text;
            if (!text.empty())
                text += "\\addlinespace\n";
            text += heading_line(part, text_latex(source[r][*heads], layout.styles[*heads]));
        }
        text += row_lines(table, layout, part, row, is_footer, r);
    }
    return text;
}

// What every float of a part says alike.
struct PartText {
    std::size_t number = 0; // from 1
    std::size_t parts = 0;
    std::string caption;
    std::string label;
    std::string notes; // under its first float
    std::string header_row;
};

// The comments above a float: where it comes from, what it needs, why it is as it is.
std::string float_comments(const Table& table, const TableLayout& layout, const Part& part,
                           const PartText& text, const std::vector<RowRange>& floats, std::size_t f) {
    std::string parts_said;
    if (text.parts > 1)
        parts_said += "; part " + std::to_string(text.number) + " of " + std::to_string(text.parts);
    if (floats.size() > 1)
        parts_said += "; rows " + std::to_string(floats[f].first + 1) + "-" +
                      std::to_string(floats[f].second) + " of " + std::to_string(layout.body.size());
    std::string out = "% " + table.title + " (written by mhbench report)" + parts_said + "\n";
    out += "% Needs \\usepackage{booktabs,array" + std::string(part.resize ? ",graphicx" : "") + "}.\n";
    if (part.wide)
        out += "% table*: wider than one column of a two-column paper (252 pt), so it spans both "
               "there; in one column it is a plain table.\n";
    if (f == 0 && floats.size() > 1)
        out += "% Too tall for one page: its rows continue in the next " +
               std::string(floats.size() == 2 ? "float" : std::to_string(floats.size() - 1) + " floats") +
               ", under the same number.\n";
    return out;
}

// Float `f` of a part: the first has the caption, the label and the notes; the others the same
// table number and the caption with "(continued)"; the last has the footer rows.
std::string write_float(const Table& table, const TableLayout& layout, const Part& part, const PartText& text,
                        const std::vector<RowRange>& floats, std::size_t f) {
    std::string rows = rows_text(table, layout, part, false, floats[f].first, floats[f].second);
    if (f + 1 == floats.size())
        if (const std::string summary = rows_text(table, layout, part, true, 0, layout.footer.size());
            !summary.empty())
            rows += "\\midrule\n" + summary;
    const std::string environment = part.wide ? "table*" : "table";
    std::string out = float_comments(table, layout, part, text, floats, f);
    out += "\\begin{" + environment + "}[htbp]\n\\centering\n";
    if (f == 0)
        out += "\\caption{" + text.caption + "}\n\\label{" + text.label + "}\n";
    else
        out += "\\addtocounter{table}{-1}\n\\caption{" + text.caption + " (continued)}\n";
    out += "\\footnotesize\n\\setlength{\\tabcolsep}{" +
           std::string(layout.sep == column_sep ? "4pt" : "3pt") + "}\n";
    if (part.resize)
        out += "% \\resizebox: one column alone is wider than the page.\n\\resizebox{\\linewidth}{!}{%\n";
    out += "\\begin{tabular}{" + part.spec + "}\n\\toprule\n" + text.header_row + "\\midrule\n" + rows +
           "\\bottomrule\n\\end{tabular}" + (part.resize ? "}" : "") + "\n";
    if (f == 0 && !text.notes.empty())
        out += "\\par\\medskip\n{\\raggedright " + text.notes + "\\par}\n";
    out += "\\end{" + environment + "}\n";
    return out;
}

// Part `p` of the table: one float, or several of consecutive rows when it is taller than a page.
std::string write_part(const Table& table, const TableLayout& layout, std::size_t p, const std::string& title,
                       const std::string& notes) {
    const Part& part = layout.parts[p];
    PartText text;
    text.number = p + 1;
    text.parts = layout.parts.size();
    text.caption = title;
    if (layout.parts.size() > 1)
        text.caption += " (" + std::string(part.name.empty() ? "" : latex_escape(part.name) + "; ") +
                        "part " + std::to_string(p + 1) + " of " + std::to_string(layout.parts.size()) + ")";
    text.label = "tab:" + table.id;
    if (p > 0) { // appended, not "-" + number: GCC 12 sees a false overlap (-Wrestrict) in that
        text.label += '-';
        text.label += std::to_string(p + 1);
    }
    text.notes = p == 0 ? notes : "Notes as for Table~\\ref{tab:" + table.id + "}.";
    for (std::size_t i = 0; i < part.columns.size(); ++i)
        text.header_row += (i == 0 ? "" : " & ") + header_cell(layout.columns[part.columns[i]]);
    text.header_row += " \\\\\n";
    const std::vector<RowRange> floats = row_floats(table, layout, part, text.caption, text.notes);
    std::string out;
    for (std::size_t f = 0; f < floats.size(); ++f)
        out += write_float(table, layout, part, text, floats, f);
    return out;
}

} // namespace
} // namespace mhb::latex_detail

namespace mhb {

std::string render_latex(const Table& table) {
    using namespace latex_detail; // this function writes what the layout's files decide
    TableLayout layout = lay_out_columns(table);
    split_into_parts(layout);
    const std::string title = latex_escape(caption_title(table));
    const std::string notes = table_notes(table, layout);
    std::string out;
    for (std::size_t p = 0; p < layout.parts.size(); ++p)
        out += write_part(table, layout, p, title, notes);
    return out;
}

std::string latex_methods(const std::vector<Table>& tables) {
    std::vector<std::string> said;
    for (const auto& t : tables)
        for (const auto& paragraph : t.methods)
            if (std::find(said.begin(), said.end(), paragraph) == said.end())
                said.push_back(paragraph);
    if (said.empty())
        return "";
    std::string out =
        "% The methods behind the tables' markers and tests (written by mhbench report), said once\n"
        "% for every table: \\input it where the paper describes its statistics.\n";
    // \sloppy: the narrow column of a two-column class has no room for the test names' long words.
    out += "{\\sloppy\n";
    for (const auto& text : said)
        out += latex_prose(text) + "\\par\n";
    return out + "}\n";
}

} // namespace mhb
