// The LaTeX of a number in its column's format (results/table_model/number_format.hpp): maths (a true
// minus, m x 10^e) padded with \phantom to the column's widest tail (fraction digits, exponent), so
// that in a right-aligned column every decimal point lines up without any package; inf is \infty
// and NaN the em dash (---), aligned on the units digit.
#pragma once

#include <string>

#include "results/table_model/number_format.hpp" // a renderer formats per column

namespace mhb {

// LaTeX of a number in a column of this format: `body` (math mode, without its $...$) and `pad`, a
// \phantom of what the column's widest tail has and this number lacks, so that every decimal point
// lines up; `width` is the estimated width of both in pt at \footnotesize (for the table layout).
struct LatexNumber {
    std::string body;
    std::string pad;
    double width = 0.0;
    [[nodiscard]] std::string math() const { return "$" + body + pad + "$"; }
};
LatexNumber latex_number(double value, const NumberFormat& format);

// Width in pt of a digit at \footnotesize (Latin Modern, 8 pt): all digits have it.
inline constexpr double latex_digit_width = 4.25;

} // namespace mhb
