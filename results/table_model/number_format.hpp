// One format for every number of a table column, so that a column reads as a paper's does:
//  - fixed notation, every number with the same significant digits and its trailing zeros kept
//    ("33.260", "4340.7", "0.017200"), when the column spans at most four decades between 1e-3
//    and 1e6 (integers stay integers: counts, rank statistics; integers and halves get one decimal);
//  - scientific notation otherwise, every mantissa with the same digits ("2.8940e-09");
//  - exactly `decimals` digits after the point where a cell asks for them (a percentage).
// Markdown shows the plain text (plain_number). LaTeX typesets the number in maths (a true minus,
// m x 10^e) and pads it with \phantom to the column's widest tail (fraction digits, exponent), so
// that in a right-aligned column every decimal point lines up without any package.
// inf is "inf" (LaTeX: \infty) and NaN the em dash (LaTeX: ---), aligned on the units digit.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "results/table_model/table.hpp"

namespace mhb {

struct NumberFormat {
    bool scientific = false;
    int significant = 5;     // fixed and scientific: significant digits of every number
    int fixed_decimals = -1; // >= 0: every number with exactly these decimals instead
    bool integers = false;   // every value is an integer: no point at all
    // The widest tail of the column, which LaTeX pads every number to:
    int max_decimals = 0;           // digits after the point (fixed) or in the mantissa (scientific)
    int exponent_digits = 0;        // scientific: the most digits of an exponent
    bool negative_exponent = false; // scientific: some exponent is negative
};

// The format of a column holding `values` (non-finite ones are ignored when choosing).
NumberFormat choose_number_format(const std::vector<double>& values, Digits digits);

// The number as Markdown shows it: "33.260", "-1.7200e-02", "inf", the em dash for NaN.
std::string plain_number(double value, const NumberFormat& format);

// The formats of one column: per group (TableCell::group), of its numbers and of their spreads.
struct ColumnFormats {
    std::map<int, NumberFormat> numbers;
    std::map<int, NumberFormat> spreads;
};
// Per column of `table`, over its rows and footer rows.
std::vector<ColumnFormats> column_formats(const Table& table);

// The pieces of a number that its renderings share (the LaTeX one is results/latex/latex_numbers.hpp).
// "-2.8940e-09" split: sign, the mantissa's digits before and after the point, the exponent.
struct Scientific {
    bool negative = false;
    std::string integer;
    std::string fraction;
    int exponent = 0;
};
Scientific scientific_parts(double value, int significant);
// The decimal digits of |n|.
int digit_count(int n);
// Digits after the point of `value` in a fixed-notation column.
int decimals_of(double value, const NumberFormat& format);
// "%.*f", and a value that rounds to zero is "0...", whatever its sign was.
std::string fixed_text(double value, int decimals);

} // namespace mhb
