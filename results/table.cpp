#include "results/table.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "results/csv.hpp"

namespace mhb {

void Table::add_row(std::vector<TableCell> row) {
    if (row.size() != header.size())
        throw std::logic_error("table " + id + ": a row has " + std::to_string(row.size()) + " cells for " +
                               std::to_string(header.size()) + " columns");
    rows.push_back(std::move(row));
}

namespace {

// Markdown cells may not hold '|' (it would split the cell).
std::string markdown_text(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '|')
            out += "\\|";
        else
            out += c;
    }
    return out;
}

} // namespace

std::string render_markdown(const Table& table) {
    std::string out = "### " + table.title + "\n\n|";
    for (const auto& h : table.header)
        out.append(" ").append(markdown_text(h)).append(" |");
    out += "\n|";
    for (std::size_t c = 0; c < table.header.size(); ++c)
        out += c == 0 ? " :--- |" : " ---: |";
    out += "\n";
    for (const auto& row : table.rows) {
        out += "|";
        for (const auto& cell : row) {
            const std::string text = markdown_text(cell.text);
            out += ' ';
            if (cell.bold && !text.empty())
                out.append("**").append(text).append("**");
            else
                out += text;
            out += " |";
        }
        out += "\n";
    }
    if (!table.caption.empty())
        out += "\n" + table.caption + "\n";
    return out;
}

std::string latex_escape(const std::string& text) {
    std::string out;
    const std::string dash = undefined_text;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, dash.size(), dash) == 0) { // the em dash, without relying on inputenc
            out += "---";
            i += dash.size() - 1;
            continue;
        }
        const char c = text[i];
        switch (c) {
        case '\\':
            out += "\\textbackslash{}";
            break;
        case '&':
        case '%':
        case '$':
        case '#':
        case '_':
        case '{':
        case '}':
            out += '\\';
            out += c;
            break;
        case '~':
            out += "\\textasciitilde{}";
            break;
        case '^':
            out += "\\textasciicircum{}";
            break;
        case '<':
            out += "\\textless{}";
            break;
        case '>':
            out += "\\textgreater{}";
            break;
        case '|':
            out += "\\textbar{}";
            break;
        default:
            out += c;
        }
    }
    return out;
}

// A cell for LaTeX: escaped, with every number in e-notation typeset as m x 10^e, so that tables
// read as a paper's do ("2.9e-09" becomes $2.9\times10^{-9}$). Plain LaTeX, no package needed.
std::string latex_cell(const std::string& text) {
    const std::string escaped = latex_escape(text);
    const auto digit = [&](std::size_t i) {
        return i < escaped.size() && escaped[i] >= '0' && escaped[i] <= '9';
    };
    std::string out;
    std::size_t i = 0;
    while (i < escaped.size()) {
        // A mantissa starts at a digit (or a '-' before one) that does not continue a word.
        const bool word_before =
            i > 0 && (std::isalnum(static_cast<unsigned char>(escaped[i - 1])) != 0 || escaped[i - 1] == '.');
        const std::size_t start = i;
        std::size_t j = escaped[i] == '-' ? i + 1 : i;
        if (word_before || !digit(j)) {
            out += escaped[i++];
            continue;
        }
        while (digit(j))
            ++j;
        if (j < escaped.size() && escaped[j] == '.' && digit(j + 1))
            for (++j; digit(j);)
                ++j;
        const std::size_t mantissa_end = j;
        std::size_t k = j;
        std::string sign;
        if (k < escaped.size() && escaped[k] == 'e') {
            ++k;
            if (k < escaped.size() && (escaped[k] == '+' || escaped[k] == '-'))
                sign = escaped[k++] == '-' ? "-" : "";
        }
        if (k == mantissa_end || !digit(k)) { // no exponent: copy the number as it is
            out.append(escaped, start, mantissa_end - start);
            i = mantissa_end;
            continue;
        }
        while (k + 1 < escaped.size() && escaped[k] == '0' && digit(k + 1))
            ++k; // 1e-09 -> 10^{-9}
        std::size_t exponent_end = k;
        while (digit(exponent_end))
            ++exponent_end;
        out.append("$").append(escaped, start, mantissa_end - start).append("\\times10^{").append(sign);
        out.append(escaped, k, exponent_end - k).append("}$");
        i = exponent_end;
    }
    return out;
}

std::string render_latex(const Table& table) {
    std::string spec = "l";
    for (std::size_t c = 1; c < table.header.size(); ++c)
        spec += 'r';
    std::string out = "% " + table.title + " (written by mhbench report)\n";
    out += "\\begin{table}[htbp]\n\\centering\n\\small\n";
    out += "\\caption{" + latex_escape(table.title) +
           (table.caption.empty() ? "" : ". " + latex_escape(table.caption)) + "}\n";
    out += "\\label{tab:" + table.id + "}\n";
    out += "\\begin{tabular}{" + spec + "}\n\\toprule\n";
    for (std::size_t c = 0; c < table.header.size(); ++c)
        out.append(c == 0 ? "" : " & ").append(latex_escape(table.header[c]));
    out += " \\\\\n\\midrule\n";
    for (const auto& row : table.rows) {
        for (std::size_t c = 0; c < row.size(); ++c) {
            const std::string text = latex_cell(row[c].text);
            out.append(c == 0 ? "" : " & ");
            if (row[c].bold && !text.empty()) // \boldmath also bolds the numbers typeset in math mode
                out.append("\\textbf{\\boldmath ").append(text).append("}");
            else
                out += text;
        }
        out += " \\\\\n";
    }
    out += "\\bottomrule\n\\end{tabular}\n\\end{table}\n";
    return out;
}

std::string render_csv(const Table& table) {
    std::string out;
    for (std::size_t c = 0; c < table.header.size(); ++c)
        out.append(c == 0 ? "" : ",").append(csv_field(table.header[c]));
    out += "\n";
    for (const auto& row : table.rows) {
        for (std::size_t c = 0; c < row.size(); ++c)
            out.append(c == 0 ? "" : ",")
                .append(row[c].value.empty() && row[c].text == undefined_text
                            ? std::string()
                            : csv_field(row[c].value.empty() ? row[c].text : row[c].value));
        out += "\n";
    }
    return out;
}

std::string format_number(double value, int significant) {
    if (std::isnan(value))
        return undefined_text;
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
    return buffer;
}

std::string format_fixed(double value, int decimals) {
    if (!std::isfinite(value))
        return format_number(value);
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

TableCell number_cell(double value, int significant) {
    // An undefined value: the dash, written to CSV as an empty field (render_csv).
    return {format_number(value, significant), std::isnan(value) ? "" : csv_number(value), false};
}

TableCell text_cell(std::string text) {
    return {std::move(text), "", false};
}

} // namespace mhb
