// The layout of a LaTeX table, decided before TeX runs (the rules are in latex_table.hpp), shared by
// the files that make it: the cells in LaTeX with their widths (latex_cells.cpp), which columns stay
// and how wide they are (latex_columns.cpp), how the columns split into parts that fit the page
// (latex_column_parts.cpp) and how a part's rows split into floats that fit it (latex_row_floats.cpp);
// latex_table.cpp writes the text. Internal to results/latex/: the table model stays free of it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "results/table_model/number_format.hpp" // a renderer formats per column
#include "results/table_model/table.hpp"         // a renderer sees tables, never runs

namespace mhb::latex_detail {

inline constexpr double page_width = 345.0;  // \textwidth of a one-column article, 10 pt, default geometry
inline constexpr double ieee_column = 252.0; // \columnwidth of a two-column IEEE paper
inline constexpr double column_sep = 4.0;    // \tabcolsep of every table...
inline constexpr double tight_sep = 3.0;     // ...but one that fits in one part with this and not with that
inline constexpr double usable_width = 0.96 * page_width;

// A cell in LaTeX and the width it takes on one line.
struct Cell {
    std::string latex;
    double width = 0.0;
    std::string below; // the spread's line (Table::latex_spread_below)
    double below_width = 0.0;
    bool empty = true;
    // "no successful run" in a column of numbers: it may span the empty cells after it.
    bool text_in_numbers = false;
};

// A column of the table that stays a column (not folded into the notes, not a heading).
struct Column {
    std::size_t index = 0; // in the Table
    LatexColumn style;
    bool numeric = false;
    std::vector<std::string> header_lines;
    double natural = 0.0; // on one line
    double least = 0.0;   // wrapped as far as it goes
    bool wrap = false;
};

// One table of a table split by columns, in LaTeX: the key columns and the columns of its groups.
struct Part {
    std::vector<std::size_t> columns; // positions in the kept columns
    std::string name;                 // its groups, for the caption
    bool resize = false;
    // Fitted to the part: the width of each wrapped column, by position in the kept columns (0 for
    // the others), the tabular's column spec and its width, and whether it is wider than a column of
    // a two-column paper.
    std::vector<double> wrap_width;
    std::string spec;
    bool wide = false;
};

// What the layout decided for a whole table.
struct TableLayout {
    std::vector<LatexColumn> styles;         // one per column of the Table
    std::vector<std::string> folded;         // "Name: value." of each constant column, for the notes
    std::vector<std::string> without_values; // the names of the columns without any value
    std::vector<Column> columns;             // the kept ones
    std::optional<std::size_t> heading;      // the column whose values head runs of rows instead
    // A footer row's label (its first cell) keeps its column; otherwise it moves to the part's
    // first cell, or heads its row.
    bool footer_label_kept = false;
    std::vector<std::vector<Cell>> body;   // by row, then by kept column
    std::vector<std::vector<Cell>> footer; // the same for the footer rows
    std::vector<Part> parts;
    double sep = column_sep; // \tabcolsep
};

// Rows [first, second) of the body that one float holds.
using RowRange = std::pair<std::size_t, std::size_t>;

// latex_cells.cpp
bool blank(const TableCell& cell);
std::string text_latex(const TableCell& cell, const LatexColumn& style);
Cell render_cell(const TableCell& cell, const ColumnFormats& formats, const LatexColumn& style, bool numeric,
                 bool markers, bool spread_below);

// latex_columns.cpp: steps 1 and 2 of the layout (all but the parts).
TableLayout lay_out_columns(const Table& table);
std::string header_cell(const Column& column);

// latex_column_parts.cpp: step 3, the parts (and the tabcolsep they are made with).
void split_into_parts(TableLayout& layout);
// Whether a part shows a footer row: when it holds some of its counts.
bool footer_row_shown(const TableLayout& layout, const Part& part, const std::vector<Cell>& row);

// latex_row_floats.cpp: the rows of each float of a part, given the caption and the notes it has.
std::vector<RowRange> row_floats(const Table& table, const TableLayout& layout, const Part& part,
                                 const std::string& caption, const std::string& notes);

} // namespace mhb::latex_detail
