// A report table as data (header, rows of cells, a caption). Its renderings live with their
// formats: Markdown and CSV in results/text/, LaTeX in results/latex/ (booktabs, laid out to fit a
// one-column article), HTML in results/html/.
//
// A number cell carries its number, not only a text: every number of a column is written alike
// (format_columns: the same significant digits with trailing zeros kept, or scientific notation for
// a column spanning many decades; results/table_model/number_format.hpp), so the renderers format per column.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace mhb {

// How many digits a number wants: `significant` significant digits, or exactly `decimals` digits
// after the point when decimals >= 0 (a percentage to one decimal, say).
struct Digits {
    int significant = 5;
    int decimals = -1;
};

// How a cell's second number follows its first: "4.02 (0.016)" (a spread: std or IQR) or
// "0.3297 / 0.1%" (a value and its error in per cent, the paper's Table 4).
enum class SpreadStyle { parentheses, slash_percent };

struct TableCell {
    std::string text;  // as shown in Markdown (and the HTML page); format_columns writes it for numbers
    std::string value; // as written to CSV (full precision); empty means "same as text"
    bool bold = false; // the best value of its row or column, say

    // A number cell: the value shown, written in the format of its column (and group).
    std::optional<double> number;
    Digits digits;
    // Cells of one column with the same group share one format; a column that mixes quantities
    // (Table 3: values, spreads and percentages) gives each its own group.
    int group = 0;
    std::optional<double> spread; // the second number: the IQR of "median (IQR)", say
    Digits spread_digits{2, -1};
    SpreadStyle spread_style = SpreadStyle::parentheses;
    std::string marker; // "+", "=" or "-" after the numbers: the comparison with a reference

    // LaTeX of a text cell when escaping its text is not enough (maths, a shorter wording); empty:
    // the escaped text.
    std::string latex;
};

// How the LaTeX rendering treats a column; Markdown and CSV ignore it.
struct LatexColumn {
    std::string header; // LaTeX (maths allowed, "\\" breaks lines); empty: the header, escaped
    // A table too wide for the page is split into several that repeat the key columns; columns
    // of one group stay together where they can, and the groups name the parts.
    std::string group;
    bool key = false; // repeated in every part (Problem, Algorithm)
    // When every row holds the same text, it is said once in the notes instead of a column.
    bool fold_constant = false;
    bool wrap = false;  // long text: a ragged-right paragraph column as wide as the page allows
    bool prose = false; // text we wrote (a reading, a test's name): f*, A12, p, minus signs as maths
    // Instead of a column, a line above each run of rows with the same value (the problem of the
    // summary's rows): the table loses the column's width.
    bool heading = false;
};

struct Table {
    std::string id;      // file stem in the report directory, e.g. "table2_fitness"
    std::string title;   // one line: the Markdown heading and the LaTeX caption
    std::string caption; // what the reader must know: tests, alpha, correction, runs, sources
    std::vector<std::string> header;
    std::vector<std::vector<TableCell>> rows; // each row has header.size() cells
    // Rows under the body that sum it up (the w/t/l counts of the markers): in Markdown and LaTeX,
    // not in CSV (whose rows are all of one kind, for other tools).
    std::vector<std::vector<TableCell>> footer;
    std::vector<LatexColumn> latex; // empty, or one per column
    // LaTeX: the second number of each cell on a line of its own under the first (a compact
    // "median over (IQR)" layout) instead of beside it.
    bool latex_spread_below = false;
    // LaTeX: the notes under the table, a few lines a paper can keep ("": the caption, which Markdown
    // may make long), and the method text several tables share (what a test is, what the markers
    // mean, Holm, alpha), said once for all in methods.tex rather than under each table.
    std::string latex_note{};
    std::vector<std::string> methods{}; // paragraphs; a paragraph two tables share is said once

    void add_row(std::vector<TableCell> row);
    void add_footer(std::vector<TableCell> row);
    // The LaTeX style of column `column`, creating the defaults for every column first.
    LatexColumn& latex_column(std::size_t column);
};

// Writes the text of every number cell in its column's format (and of every composite cell:
// "median (IQR) marker"). Every table builder calls it once its rows are complete.
void format_columns(Table& table);

// What a cell shows for an undefined value (a NaN, e.g. the mean of +inf and -inf), since no table
// prints "nan": an em dash in Markdown, "---" in LaTeX, an empty field in CSV.
inline constexpr const char* undefined_text = "\u2014";

// Number formatting for single values outside a column (captions, the console): `significant`
// significant digits ("%.*g"), "inf" and "-inf" spelled out, undefined_text for NaN.
std::string format_number(double value, int significant = 5);
std::string format_fixed(double value, int decimals);

// The items with `separator` between them, for captions and notes. The separator comes only once
// something has been written, so leading empty items leave no stray separator.
std::string join(const std::vector<std::string>& items, const std::string& separator);

// A number cell (text in the single-value format until format_columns writes the column's).
TableCell number_cell(double value, int significant = 5);
TableCell fixed_cell(double value, int decimals);
// "value (spread) marker": a location, its spread and the comparison's marker ("" for none).
TableCell spread_cell(double value, double spread, const std::string& marker, Digits value_digits,
                      Digits spread_digits);
TableCell text_cell(std::string text);

} // namespace mhb
