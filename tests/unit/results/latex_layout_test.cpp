// The steps of a LaTeX table's layout one by one (results/latex/latex_layout.hpp), where
// latex_golden_test.cpp checks the text they end in: which columns fold into the notes or head runs
// of rows, that the parts of a wide table hold every column once and fit the page, and that the
// floats of a long part hold every row once, in order.
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "results/latex/latex_layout.hpp"
#include "results/table_model/table.hpp"

namespace mhb::latex_detail {
namespace {

// Problem (constant), Algorithm (key), then `columns` numbers in two groups.
Table numbers_table(std::size_t rows, std::size_t columns) {
    Table t;
    t.id = "layout";
    t.title = "Numbers";
    t.header = {"Problem", "Algorithm", "Empty"};
    for (std::size_t c = 0; c < columns; ++c)
        t.header.push_back("value number " + std::to_string(c));
    for (std::size_t r = 0; r < rows; ++r) {
        std::vector<TableCell> row = {text_cell("sphere:dim=2"), text_cell("algorithm" + std::to_string(r)),
                                      text_cell("")};
        for (std::size_t c = 0; c < columns; ++c)
            row.push_back(number_cell(1234.5678 * static_cast<double>(r + c + 1), 8));
        t.add_row(std::move(row));
    }
    t.latex_column(0).fold_constant = true;
    t.latex_column(1).key = true;
    for (std::size_t c = 0; c < columns; ++c)
        t.latex_column(3 + c).group = c % 2 == 0 ? "even" : "odd";
    format_columns(t);
    return t;
}

TEST(LatexLayoutSteps, ConstantAndEmptyColumnsGoToTheNotesAndAHeadingColumnHeadsRuns) {
    Table t = numbers_table(4, 2);
    t.latex_column(1).heading = true; // the algorithm heads runs of rows instead of being a column
    const TableLayout layout = lay_out_columns(t);
    ASSERT_EQ(layout.folded.size(), 1u);
    EXPECT_EQ(layout.folded.front(), "Problem: sphere:\\allowbreak{}dim=2.");
    EXPECT_EQ(layout.without_values, std::vector<std::string>{"Empty"});
    EXPECT_EQ(layout.heading, std::size_t{1});
    ASSERT_EQ(layout.columns.size(), 2u);
    EXPECT_EQ(layout.columns.front().index, 3u);
    EXPECT_EQ(layout.body.size(), 4u);
    EXPECT_EQ(layout.body.front().size(), layout.columns.size());
}

TEST(LatexLayoutSteps, TheColumnsOfAWideTableAreSplitIntoPartsThatFitThePage) {
    TableLayout layout = lay_out_columns(numbers_table(3, 14));
    split_into_parts(layout);
    ASSERT_GE(layout.parts.size(), 2u);
    std::vector<int> seen(layout.columns.size(), 0);
    for (const Part& part : layout.parts) {
        EXPECT_EQ(part.columns.front(), 0u); // the key column first in every part
        double width = 0.0;
        for (std::size_t k : part.columns) {
            seen[k] += 1;
            width += layout.columns[k].natural + 2 * layout.sep;
        }
        EXPECT_FALSE(part.resize);
        EXPECT_LE(width, usable_width);
        EXPECT_EQ(part.spec.size(), part.columns.size()); // "lrr...": no wrapped column here
        EXPECT_FALSE(part.name.empty());
    }
    EXPECT_EQ(seen.front(), static_cast<int>(layout.parts.size()));
    for (std::size_t k = 1; k < seen.size(); ++k)
        EXPECT_EQ(seen[k], 1) << k;
}

TEST(LatexLayoutSteps, TheFloatsOfALongPartHoldEveryRowOnceInOrder) {
    const Table t = numbers_table(150, 2);
    TableLayout layout = lay_out_columns(t);
    split_into_parts(layout);
    ASSERT_EQ(layout.parts.size(), 1u);
    const std::vector<RowRange> floats = row_floats(t, layout, layout.parts.front(), "Numbers", "");
    ASSERT_GE(floats.size(), 3u); // 150 rows of 9.8 pt: more than two pages
    std::size_t next = 0;
    for (const RowRange& range : floats) {
        EXPECT_EQ(range.first, next);
        EXPECT_GT(range.second, range.first);
        next = range.second;
    }
    EXPECT_EQ(next, 150u);
    // As evenly filled as they can be: no float holds many more rows than another.
    EXPECT_LE(floats.front().second - floats.front().first, floats.back().second - floats.back().first + 8);
}

} // namespace
} // namespace mhb::latex_detail
