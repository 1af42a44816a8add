// The cells of a LaTeX table: each in LaTeX (numbers padded so their decimal points line up, a
// spread beside or below, the comparison's marker, bold) with the width it takes, which the layout
// (latex_layout.hpp) needs before TeX runs.
#include <string>

#include "results/latex/latex_layout.hpp"
#include "results/latex/latex_numbers.hpp"
#include "results/latex/latex_text.hpp"

namespace mhb::latex_detail {

namespace {

constexpr double space = 2.67;
constexpr double marker_width = 6.61;

} // namespace

bool blank(const TableCell& cell) {
    return !cell.number && cell.text.empty();
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

} // namespace mhb::latex_detail
