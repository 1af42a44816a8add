#include "results/latex_numbers.hpp"

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

// "-2.8940e-09" split: sign, the mantissa's digits before and after the point, the exponent.
struct Scientific {
    bool negative = false;
    std::string integer;
    std::string fraction;
    int exponent = 0;
};

Scientific scientific_parts(double value, int significant) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*e", std::max(0, significant - 1), value);
    const std::string text = buffer;
    Scientific s;
    std::size_t i = 0;
    if (text[i] == '-') {
        s.negative = true;
        ++i;
    }
    const std::size_t e = text.find('e');
    const std::string mantissa = text.substr(i, e - i);
    const std::size_t point = mantissa.find('.');
    s.integer = mantissa.substr(0, point);
    s.fraction = point == std::string::npos ? "" : mantissa.substr(point + 1);
    s.exponent = std::atoi(text.c_str() + e + 1);
    return s;
}

int digit_count(int n) {
    int digits = 1;
    for (n = std::abs(n); n >= 10; n /= 10)
        ++digits;
    return digits;
}

// Digits after the point of `value` in a fixed-notation column.
int decimals_of(double value, const NumberFormat& format) {
    if (format.integers)
        return 0;
    if (format.fixed_decimals >= 0)
        return format.fixed_decimals;
    return std::max(0, format.significant - 1 - scientific_parts(value, format.significant).exponent);
}

std::string fixed_text(double value, int decimals) {
    char buffer[400];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    std::string text = buffer;
    // A value that rounds to zero is zero, whatever its sign was.
    if (text[0] == '-' && text.find_first_not_of("-0.") == std::string::npos)
        text.erase(0, 1);
    return text;
}

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

NumberFormat choose_number_format(const std::vector<double>& values, Digits digits) {
    NumberFormat format;
    format.significant = std::max(1, digits.significant);
    format.fixed_decimals = digits.decimals;
    bool all_integers = true;
    double largest = 0.0;
    std::vector<int> exponents;
    for (double v : values) {
        if (!std::isfinite(v))
            continue;
        all_integers = all_integers && v == std::round(v);
        largest = std::max(largest, std::fabs(v));
        if (v != 0.0)
            exponents.push_back(scientific_parts(v, format.significant).exponent);
    }
    if (digits.decimals >= 0) {
        format.max_decimals = digits.decimals;
        return format;
    }
    if ((all_integers && largest < 1e6) || exponents.empty()) {
        format.integers = true;
        return format;
    }
    // Integers and halves (rank statistics with ties, medians of counts): one decimal, not 25.0000.
    if (largest < 1e6 && std::all_of(values.begin(), values.end(), [](double v) {
            return !std::isfinite(v) || 2.0 * v == std::round(2.0 * v);
        })) {
        format.fixed_decimals = 1;
        format.max_decimals = 1;
        return format;
    }
    const auto [lowest, highest] = std::minmax_element(exponents.begin(), exponents.end());
    if (*highest <= 5 && *lowest >= -3 && *highest - *lowest <= 3) {
        for (double v : values)
            if (std::isfinite(v) && v != 0.0)
                format.max_decimals = std::max(format.max_decimals, decimals_of(v, format));
        return format;
    }
    format.scientific = true;
    format.max_decimals = format.significant - 1;
    for (int e : exponents) {
        format.exponent_digits = std::max(format.exponent_digits, digit_count(e));
        format.negative_exponent = format.negative_exponent || e < 0;
    }
    return format;
}

std::string plain_number(double value, const NumberFormat& format) {
    if (std::isnan(value))
        return undefined_text;
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    if (value == 0.0 && format.fixed_decimals < 0)
        return "0";
    if (!format.scientific)
        return fixed_text(value, decimals_of(value, format));
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*e", format.significant - 1, value);
    return buffer;
}

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

std::vector<ColumnFormats> column_formats(const Table& table) {
    std::vector<ColumnFormats> out(table.header.size());
    for (std::size_t c = 0; c < table.header.size(); ++c) {
        // Per group: the values, and the digits asked for (the most any cell of the group asks).
        std::map<int, std::pair<std::vector<double>, Digits>> numbers;
        std::map<int, std::pair<std::vector<double>, Digits>> spreads;
        const auto gather = [&](const TableCell& cell) {
            if (!cell.number)
                return;
            const auto add = [](std::pair<std::vector<double>, Digits>& into, double v, Digits d,
                                bool first) {
                into.first.push_back(v);
                if (first) {
                    into.second = d;
                    return;
                }
                into.second.significant = std::max(into.second.significant, d.significant);
                into.second.decimals = std::max(into.second.decimals, d.decimals);
            };
            add(numbers[cell.group], *cell.number, cell.digits, numbers[cell.group].first.empty());
            if (cell.spread)
                add(spreads[cell.group], *cell.spread, cell.spread_digits, spreads[cell.group].first.empty());
        };
        for (const auto* rows : {&table.rows, &table.footer})
            for (const auto& row : *rows)
                if (c < row.size())
                    gather(row[c]);
        for (const auto& [group, values] : numbers)
            out[c].numbers[group] = choose_number_format(values.first, values.second);
        for (const auto& [group, values] : spreads)
            out[c].spreads[group] = choose_number_format(values.first, values.second);
    }
    return out;
}

} // namespace mhb
