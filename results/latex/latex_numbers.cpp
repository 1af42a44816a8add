#include "results/latex/latex_numbers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace mhb {

namespace {

// Widths in pt at \footnotesize (Latin Modern 8 pt, measured with pdflatex): what the layout of a
// table needs to know, not what the numbers look like.
constexpr double point_width = 2.36;
constexpr double minus_width = 6.61;   // a minus at the start of a formula
constexpr double times_ten = 18.7;     // "\times10" with the spaces around a binary operator
constexpr double script_digit = 3.67;  // a digit of an exponent
constexpr double script_minus = 5.78;  // the minus of an exponent
constexpr double script_space = 0.5;   // \scriptspace after an exponent
constexpr double infinity_width = 8.5; // \infty
constexpr double dash_width = 8.5;     // ---

std::string zeros(int n) {
    return std::string(static_cast<std::size_t>(std::max(0, n)), '0');
}

// What follows the units digit in the column's widest number, as LaTeX (for \phantom) and width.
struct Tail {
    std::string latex;
    double width = 0.0;
};
Tail full_tail(const NumberFormat& format) {
    Tail tail;
    if (format.max_decimals > 0) {
        tail.latex = std::string(".").append(zeros(format.max_decimals));
        tail.width = point_width + latex_digit_width * format.max_decimals;
    }
    if (format.scientific) {
        tail.latex += "{}\\times10^{" + std::string(format.negative_exponent ? "-" : "") +
                      zeros(format.exponent_digits) + "}";
        tail.width += times_ten + script_space + script_digit * format.exponent_digits +
                      (format.negative_exponent ? script_minus : 0.0);
    }
    return tail;
}

std::string phantom(const std::string& latex) {
    return latex.empty() ? "" : "\\phantom{" + latex + "}";
}

} // namespace

LatexNumber latex_number(double value, const NumberFormat& format) {
    const Tail tail = full_tail(format);
    LatexNumber out;
    if (!std::isfinite(value) || (value == 0.0 && format.fixed_decimals < 0)) {
        // Aligned on the units digit: what stands there, then the column's whole tail as padding.
        std::string units = "0";
        double width = latex_digit_width;
        if (std::isnan(value)) {
            units = "\\mbox{---}";
            width = dash_width;
        } else if (std::isinf(value)) {
            units = value > 0 ? "\\infty" : "-\\infty";
            width = infinity_width + (value > 0 ? 0.0 : minus_width);
        }
        out.body = units;
        out.pad = phantom(tail.latex);
        out.width = width + tail.width;
        return out;
    }
    if (!format.scientific) {
        const std::string text = fixed_text(value, decimals_of(value, format));
        const bool negative = text[0] == '-';
        const std::string digits = negative ? text.substr(1) : text;
        const std::size_t point = digits.find('.');
        const int decimals = point == std::string::npos ? 0 : static_cast<int>(digits.size() - point - 1);
        const std::size_t integer_digits = point == std::string::npos ? digits.size() : point;
        std::string pad;
        if (decimals < format.max_decimals)
            pad = (decimals == 0 ? "." : "") + zeros(format.max_decimals - decimals);
        out.body = std::string(negative ? "-" : "") + digits;
        out.pad = phantom(pad);
        out.width = (negative ? minus_width : 0.0) + latex_digit_width * static_cast<double>(integer_digits) +
                    tail.width;
        return out;
    }
    const Scientific s = scientific_parts(value, format.significant);
    std::string pad;
    if (format.negative_exponent && s.exponent >= 0)
        pad += "-";
    pad += zeros(format.exponent_digits - digit_count(s.exponent));
    out.body = std::string(s.negative ? "-" : "") + s.integer + (s.fraction.empty() ? "" : "." + s.fraction) +
               "\\times10^{" + std::to_string(s.exponent) + "}";
    out.pad = pad.empty() ? "" : "\\phantom{\\scriptstyle " + pad + "}";
    out.width = (s.negative ? minus_width : 0.0) + latex_digit_width * static_cast<double>(s.integer.size()) +
                tail.width;
    return out;
}

} // namespace mhb
