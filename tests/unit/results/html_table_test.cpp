// render_html_table: a report table as a plain, escaped HTML table that the page's script can sort.
#include <gtest/gtest.h>
#include <limits>
#include <string>

#include "results/html/html_escape.hpp"
#include "results/html/html_table.hpp"
#include "support/table_cells.hpp"

namespace mhb {
namespace {

using mhb::test_support::cell;

Table sample_table() {
    Table t;
    t.id = "tests";
    t.title = "Tests <against> \"itlbo\" & co";
    t.caption = "Holm's correction, alpha = 0.05 & 5 runs <each>.";
    t.header = {"Problem", "Runs", "p", "Result"};
    t.add_row({text_cell("sphere:dim=2"), text_cell("5/5"), cell("0.0012", "0.00123456789", false),
               text_cell("+")});
    t.add_row({text_cell("a<b>&\"c\""), text_cell("4/5"),
               number_cell(std::numeric_limits<double>::infinity()), cell("=", "", true)});
    t.add_row({text_cell("pmsm"), text_cell("0/5"), text_cell(undefined_text), text_cell("-")});
    return t;
}

TEST(HtmlTable, EscapesEveryTextAndKeepsTheStructure) {
    const std::string html = render_html_table(sample_table(), "t-tests", 3);
    EXPECT_NE(html.find("<section class=\"table\" id=\"t-tests\">"), std::string::npos);
    EXPECT_NE(html.find("<h3>Tests &lt;against&gt; &quot;itlbo&quot; &amp; co</h3>"), std::string::npos);
    EXPECT_NE(html.find("Holm&#39;s correction, alpha = 0.05 &amp; 5 runs &lt;each&gt;."), std::string::npos);
    EXPECT_NE(html.find(">a&lt;b&gt;&amp;&quot;c&quot;</td>"), std::string::npos);
    EXPECT_EQ(html.find("<against>"), std::string::npos);
    EXPECT_EQ(html.find("a<b>"), std::string::npos);
    EXPECT_NE(html.find("<table class=\"sortable\" aria-describedby=\"t-tests-caption\">"),
              std::string::npos);
    EXPECT_NE(html.find("<thead><tr><th scope=\"col\" class=\"l\">Problem</th>"), std::string::npos);
    std::size_t rows = 0;
    for (std::size_t at = html.find("<tr>"); at != std::string::npos; at = html.find("<tr>", at + 1))
        ++rows;
    EXPECT_EQ(rows, 4u); // the header and three rows
}

TEST(HtmlTable, CarriesFullPrecisionBoldAndAlignment) {
    const std::string html = render_html_table(sample_table(), "x", 4);
    EXPECT_NE(html.find("<td data-value=\"0.00123456789\">0.0012</td>"), std::string::npos) << html;
    EXPECT_NE(html.find("<td>inf</td>"),
              std::string::npos); // "p" is numeric: inf and the dash do not change that
    EXPECT_NE(html.find("<td class=\"l\"><strong>=</strong></td>"), std::string::npos);
    EXPECT_NE(html.find("<th scope=\"col\">Runs</th>"), std::string::npos); // "5/5" starts with a number
    EXPECT_NE(html.find("<th scope=\"col\" class=\"l\">Result</th>"), std::string::npos);
    EXPECT_NE(html.find("<h4>"), std::string::npos);
}

TEST(HtmlTable, LongCellsWrap) {
    Table t;
    t.id = "effects";
    t.title = "Effects";
    t.header = {"Reading"};
    t.add_row({text_cell("tutorial on lowers log10(f - f*) by 2.3: helps, and says so at length")});
    EXPECT_NE(render_html_table(t, "e", 3).find("<td class=\"l long\">"), std::string::npos);
}

TEST(HtmlEscape, EscapesMarkupAndMakesAnchors) {
    EXPECT_EQ(html_escape("<a href=\"x\">'&'</a>"), "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt;");
    EXPECT_EQ(html_escape("plain \xe2\x80\x94 text"), "plain \xe2\x80\x94 text");
    EXPECT_EQ(html_anchor("table2_fitness"), "table2_fitness");
    EXPECT_EQ(html_anchor("pmsm:load=2,speed=2500"), "pmsm-load-2-speed-2500");
    EXPECT_EQ(html_anchor(""), "-");
}

TEST(HtmlTable, FooterRowsAreATfootAfterTheBody) {
    Table t = sample_table();
    t.add_footer({text_cell("w/t/l"), text_cell(""), text_cell(""), text_cell("1/1/1")});
    const std::string html = render_html_table(t, "t-tests", 3);
    const auto body_end = html.find("</tbody>");
    const auto foot = html.find("<tfoot>\n<tr><td class=\"l\">w/t/l</td>");
    ASSERT_NE(body_end, std::string::npos);
    ASSERT_NE(foot, std::string::npos);
    EXPECT_LT(body_end, foot);
    // The footer follows the columns' order on the page: Result right after Problem.
    EXPECT_NE(html.find("w/t/l</td><td class=\"l\">1/1/1</td>"), std::string::npos);
    EXPECT_EQ(render_html_table(sample_table(), "t-tests", 3).find("<tfoot>"), std::string::npos);
}

TEST(HtmlTable, ShowsTheDecisiveColumnsAfterTheKeysAndColoursAlgorithms) {
    EXPECT_EQ(html_column_order({"Problem", "Algorithm", "W", "p", "p (Holm)", "A12", "Result", "Result by"}),
              (std::vector<std::size_t>{0, 1, 4, 6, 2, 3, 5, 7}));
    EXPECT_EQ(html_column_order({"Mean", "Reading"}), (std::vector<std::size_t>{1, 0}));
    const std::string html = render_html_table(sample_table(), "t", 3);
    EXPECT_NE(
        html.find("<th scope=\"col\" class=\"l\">Problem</th><th scope=\"col\" class=\"l\">Result</th>"),
        std::string::npos);
    Table t;
    t.header = {"Algorithm", "Mean"};
    t.add_row({text_cell("pso"), number_cell(1.0)});
    t.add_row({text_cell("tlbo"), number_cell(2.0)});
    const std::string coloured = render_html_table(t, "c", 3, {{"pso", "#2ca02c"}});
    EXPECT_NE(
        coloured.find("<td class=\"l\"><span class=\"swatch\" style=\"background:#2ca02c\"></span>pso</td>"),
        std::string::npos);
    EXPECT_NE(coloured.find("<td class=\"l\">tlbo</td>"), std::string::npos);
}

} // namespace
} // namespace mhb
