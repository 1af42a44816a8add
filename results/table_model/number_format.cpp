#include "results/table_model/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace mhb {

int digit_count(int n) {
    int digits = 1;
    for (n = std::abs(n); n >= 10; n /= 10)
        ++digits;
    return digits;
}

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
