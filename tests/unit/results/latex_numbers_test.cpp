// One format per table column (results/latex/latex_numbers.hpp): the same significant digits with
// trailing zeros kept, scientific notation for a column spanning many decades, true minus signs,
// inf and the em dash, and LaTeX padding that lines every decimal point up in a plain `r` column.
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

#include "results/latex/latex_numbers.hpp"
#include "results/table_model/number_format.hpp"
#include "results/table_model/table.hpp"
#include "results/text/csv_table.hpp"
#include "results/text/markdown_table.hpp"
#include "support/numbers.hpp"

namespace mhb {
namespace {

using mhb::test_support::inf;
constexpr double quiet_nan = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string> plain(const std::vector<double>& values, Digits digits) {
    const NumberFormat format = choose_number_format(values, digits);
    std::vector<std::string> out;
    for (double v : values)
        out.push_back(plain_number(v, format));
    return out;
}

TEST(ColumnFormat, SameSignificantDigitsWithTrailingZeros) {
    // Two decades: fixed notation, five significant digits each, zeros kept.
    EXPECT_EQ(plain({33.26, 4340.73, 17.2}, {5, -1}),
              (std::vector<std::string>{"33.260", "4340.7", "17.200"}));
    EXPECT_EQ(plain({0.0172, 0.5}, {3, -1}), (std::vector<std::string>{"0.0172", "0.500"}));
}

TEST(ColumnFormat, ScientificWhenTheColumnSpansManyDecades) {
    // 0.0172 to 4340: five decades, so every number in scientific notation with one mantissa format.
    EXPECT_EQ(plain({33.26, 0.0172, 4340.73}, {5, -1}),
              (std::vector<std::string>{"3.3260e+01", "1.7200e-02", "4.3407e+03"}));
    // Small values alone are scientific too (below 1e-3).
    EXPECT_EQ(plain({2.9e-9, 3.1e-9}, {3, -1}), (std::vector<std::string>{"2.90e-09", "3.10e-09"}));
}

TEST(ColumnFormat, IntegersHalvesAndFixedDecimals) {
    EXPECT_EQ(plain({0, 43, 210}, {6, -1}), (std::vector<std::string>{"0", "43", "210"}));
    // Rank statistics with ties: one decimal, not 25.0000.
    EXPECT_EQ(plain({25, 22.5}, {6, -1}), (std::vector<std::string>{"25.0", "22.5"}));
    // A percentage to one decimal: exactly one, whatever the magnitude; -0.04 rounds to 0.0.
    EXPECT_EQ(plain({0.04, 12.94, -0.04}, {1, 1}), (std::vector<std::string>{"0.0", "12.9", "0.0"}));
}

TEST(ColumnFormat, InfinityAndUndefinedAreSpelledOutAndIgnoredForTheFormat) {
    EXPECT_EQ(plain({1.5, inf, -inf, quiet_nan, 2.25}, {3, -1}),
              (std::vector<std::string>{"1.50", "inf", "-inf", undefined_text, "2.25"}));
    const NumberFormat format = choose_number_format({1.25, inf, quiet_nan}, {3, -1});
    EXPECT_EQ(latex_number(inf, format).math(), "$\\infty\\phantom{.00}$");
    EXPECT_EQ(latex_number(-inf, format).math(), "$-\\infty\\phantom{.00}$");
    EXPECT_EQ(latex_number(quiet_nan, format).math(), "$\\mbox{---}\\phantom{.00}$");
}

TEST(LatexNumber, TrueMinusSignsAndPowersOfTen) {
    const NumberFormat fixed = choose_number_format({-0.084, 0.5}, {3, -1});
    EXPECT_EQ(latex_number(-0.084, fixed).math(), "$-0.0840$"); // maths: a minus, not a hyphen
    EXPECT_EQ(latex_number(0.5, fixed).math(), "$0.500\\phantom{0}$");
    const NumberFormat scientific = choose_number_format({4.066e-3, 2.915e-9, 1.034, -250.0}, {4, -1});
    EXPECT_EQ(latex_number(2.915e-9, scientific).math(), "$2.915\\times10^{-9}$");
    // Exponents padded to the column's widest (a minus and one digit here): the points line up.
    EXPECT_EQ(latex_number(1.034, scientific).math(), "$1.034\\times10^{0}\\phantom{\\scriptstyle -}$");
    EXPECT_EQ(latex_number(-250.0, scientific).math(), "$-2.500\\times10^{2}\\phantom{\\scriptstyle -}$");
    EXPECT_EQ(latex_number(0.0, scientific).math(), "$0\\phantom{.000{}\\times10^{-0}}$");
}

TEST(LatexNumber, EveryNumberOfAColumnEndsAtTheSameDistanceFromItsPoint) {
    // In a right-aligned column, equal widths right of the units digit put every point in line:
    // the estimated width minus the integer part must be the same for every number.
    const std::vector<double> values = {33.26, 4340.73, 17.2, 0.0, inf};
    const NumberFormat format = choose_number_format(values, {5, -1});
    const double units = latex_digit_width;
    EXPECT_DOUBLE_EQ(latex_number(33.26, format).width - 2 * units,
                     latex_number(4340.73, format).width - 4 * units);
    EXPECT_DOUBLE_EQ(latex_number(17.2, format).width - 2 * units, latex_number(0.0, format).width - units);
}

TEST(FormatColumns, WritesEachColumnAlikeAndKeepsTheCsvFullPrecision) {
    Table t{"t", "t", "", {"name", "value", "median (IQR)"}, {}, {}, {}, false};
    t.add_row({text_cell("a"), number_cell(0.5, 3), spread_cell(1.0 / 3.0, 0.25, "+", {3, -1}, {2, -1})});
    t.add_row({text_cell("b"), number_cell(0.0172, 3), spread_cell(2.0, 0.126, "", {3, -1}, {2, -1})});
    format_columns(t);
    EXPECT_EQ(t.rows[0][1].text, "0.500");
    EXPECT_EQ(t.rows[1][1].text, "0.0172");
    EXPECT_EQ(t.rows[0][2].text, "0.333 (0.25) +");
    EXPECT_EQ(t.rows[1][2].text, "2.00 (0.13)");
    EXPECT_EQ(render_csv(t),
              "name,value,median (IQR)\na,0.5,0.3333333333333333 (0.25) +\nb,0.0172,2 (0.126)\n");
    // Markdown: text columns left, number columns right.
    EXPECT_NE(render_markdown(t).find("| :--- | ---: | ---: |"), std::string::npos) << render_markdown(t);
}

TEST(FormatColumns, GroupsOfOneColumnEachHaveTheirOwnFormat) {
    Table t{"t", "t", "", {"quantity", "Rs"}, {}, {}, {}, false};
    TableCell value = number_cell(0.32972, 5);
    TableCell percent = fixed_cell(-0.0846, 3);
    percent.group = 1;
    t.add_row({text_cell("mean"), value});
    t.add_row({text_cell("error %"), percent});
    format_columns(t);
    EXPECT_EQ(t.rows[0][1].text, "0.32972");
    EXPECT_EQ(t.rows[1][1].text, "-0.085"); // three decimals, not the values' five significant digits
}

} // namespace
} // namespace mhb
