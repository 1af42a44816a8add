// The HTML report (index.html and a page per budget): the verdict first and the study's metadata
// last; every table and caption, escaped; the figures as PNG images linking their PDF, the key ones
// first; nothing that would load from outside the report; pages that link each other and stay small;
// the same bytes when written twice; and a clear note where figures are missing.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "results/html/html_escape.hpp"
#include "results/html/html_report.hpp"
#include "results/report/report.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"
#include "support/files.hpp"
#include "support/table_cells.hpp"
#include "support/text.hpp"

namespace mhb {
namespace {

namespace fs = std::filesystem;
using mhb::test_support::read_text;

using mhb::test_support::count;

// The values of every `marker`...`end` in `text`, e.g. every id="..." or url(#...).
std::vector<std::string> values_after(const std::string& text, const std::string& marker, char end) {
    std::vector<std::string> values;
    for (std::size_t at = text.find(marker); at != std::string::npos; at = text.find(marker, at + 1)) {
        const std::size_t start = at + marker.size();
        values.push_back(text.substr(start, text.find(end, start) - start));
    }
    return values;
}

using mhb::test_support::cell;

Table table(const std::string& id, const std::string& title, const std::string& caption) {
    Table t;
    t.id = id;
    t.title = title;
    t.caption = caption;
    t.header = {"Problem", "Algorithm", "Mean"};
    t.add_row({text_cell("sphere:dim=2"), text_cell("itlbo<&>\"x\""), number_cell(0.5)});
    t.add_row({text_cell("sphere:dim=2"), text_cell("tlbo"), cell("1.5", "1.5000000001", true)});
    return t;
}

class HtmlReport : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = test_support::fresh_temporary_path("mhb_html_report_", "page");
        fs::create_directories(dir_ / "figures");
        for (const char* name :
             {"convergence_iteration_sphere_dim_2", "final_values_sphere_dim_2", "ecdf_targets_sphere_dim_2"})
            write_file(dir_ / "figures" / (std::string(name) + ".png"), "a PNG");
        write_file(dir_ / "figures" / "final_values_sphere_dim_2.svg", "<svg>not shown</svg>");
        write_file(dir_ / "figures" / ".final_values_sphere_dim_2.png.tmp-123", "a drawing in progress");

        content_.study = "/studies/<mine> & \"yours\"";
        content_.context_text = "version = 0.1.0\ngit_commit = abc123\ncompiler = GNU <12>\nthreads = 2\n"
                                "date_utc = 2026-01-01T00:00:00Z\nhostname = <script>alert(1)</script>\n";
        content_.study_text = "algorithms = itlbo tlbo\nproblems = sphere:dim=2\n";
        HtmlBudgetSection section;
        section.budget = "iterations=150";
        section.directory = dir_;
        section.tables = {table("summary", "Summary <of> runs [budget iterations=150]",
                                "Median & IQR; 5 runs \"each\" < 6. Budget: iterations=150."),
                          table("tests", "Tests", "Wilcoxon rank-sum, Holm, alpha = 0.05 > 0.01.")};
        section.verdict = {table("verdict", "Verdict per problem", "Ranked by median.")};
        content_.budgets = {section};
    }
    static void write_file(const fs::path& path, const std::string& text) {
        std::ofstream(path, std::ios::binary) << text;
    }

    fs::path dir_;
    HtmlReportContent content_;
};

TEST_F(HtmlReport, HoldsEveryTableAndEveryCaptionEscaped) {
    const std::string page = render_html_report(content_);
    EXPECT_EQ(page.rfind("<!DOCTYPE html>\n", 0), 0u);
    EXPECT_EQ(count(page, "<table"), 3u); // the verdict and both tables
    for (const auto& t : content_.budgets[0].tables) {
        EXPECT_NE(page.find(html_escape(t.caption)), std::string::npos) << t.caption;
        EXPECT_NE(page.find(html_escape(t.title)), std::string::npos) << t.title;
    }
    EXPECT_NE(page.find("Median &amp; IQR; 5 runs &quot;each&quot; &lt; 6."), std::string::npos);
    EXPECT_NE(page.find("itlbo&lt;&amp;&gt;&quot;x&quot;"), std::string::npos);
    EXPECT_EQ(page.find("itlbo<&>"), std::string::npos);
    EXPECT_EQ(page.find("<of>"), std::string::npos);
    EXPECT_EQ(page.find("<mine>"), std::string::npos);
    EXPECT_EQ(page.find("<script>alert"), std::string::npos);
    EXPECT_NE(page.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
    EXPECT_NE(page.find("<dt>Compiler</dt><dd>GNU &lt;12&gt;</dd>"), std::string::npos);
    EXPECT_NE(page.find("problems = sphere:dim=2"), std::string::npos); // study.ini
    EXPECT_EQ(count(page, "<script>"), 1u);                             // the sort script only
    // The table of contents links every table (without the budget every title repeats).
    EXPECT_NE(page.find("<a href=\"#t-summary\">Summary &lt;of&gt; runs</a>"), std::string::npos);
    EXPECT_NE(page.find("<a href=\"#t-tests\">Tests</a>"), std::string::npos);
}

TEST_F(HtmlReport, OpensWithTheVerdictAndEndsWithTheStudysMetadata) {
    const std::string page = render_html_report(content_);
    const std::size_t verdict = page.find("<section id=\"verdict\">");
    ASSERT_NE(verdict, std::string::npos);
    EXPECT_LT(page.find("<main>"), verdict);
    EXPECT_LT(verdict, page.find("<nav class=\"toc\""));
    EXPECT_LT(verdict, page.find("<section id=\"key-figures\">"));
    EXPECT_LT(page.find("<section id=\"key-figures\">"), page.find("id=\"t-summary\""));
    const std::size_t context = page.find("<section id=\"context\">");
    EXPECT_GT(context, page.find("id=\"t-tests\""));
    EXPECT_GT(context, page.find("<section id=\"figures\">"));
    EXPECT_LT(context, page.find("</main>"));
    EXPECT_GT(page.find("problems = sphere:dim=2"), context); // study.ini within the metadata
}

TEST_F(HtmlReport, ShowsEachPngFigureAsAnImageLinkingItsPdfKeyFiguresFirst) {
    const std::string page = render_html_report(content_);
    EXPECT_EQ(count(page, "<img "), 3u); // the PNG files; not the SVG, not the temporary file
    EXPECT_EQ(count(page, "<svg"), 0u);
    EXPECT_EQ(page.find("drawing in progress"), std::string::npos);
    EXPECT_NE(page.find("<a href=\"figures/final_values_sphere_dim_2.pdf\"><img "
                        "src=\"figures/final_values_sphere_dim_2.png\" loading=\"lazy\""),
              std::string::npos);
    // The key figures under "Key figures", the others under their kind below.
    const std::size_t key = page.find("<section id=\"key-figures\">");
    EXPECT_GT(page.find("src=\"figures/convergence_iteration_sphere_dim_2.png\""), key);
    EXPECT_LT(page.find("src=\"figures/convergence_iteration_sphere_dim_2.png\""),
              page.find("id=\"t-summary\""));
    EXPECT_GT(page.find("src=\"figures/ecdf_targets_sphere_dim_2.png\""),
              page.find("Fixed-target ECDFs</h3>"));

    std::multiset<std::string> ids;
    for (const auto& id : values_after(page, " id=\"", '"'))
        ids.insert(id);
    for (const auto& id : ids)
        EXPECT_EQ(ids.count(id), 1u) << "id \"" << id << "\" is not unique";
    for (const auto& href : values_after(page, "href=\"", '"')) {
        ASSERT_FALSE(href.empty());
        if (href[0] == '#')
            EXPECT_EQ(ids.count(href.substr(1)), 1u) << "href=\"" << href << "\" points to no id";
        else
            EXPECT_EQ(href.rfind("figures/", 0), 0u) << href;
    }
}

TEST_F(HtmlReport, LoadsNothingFromOutsideTheReport) {
    const std::string page = render_html_report(content_);
    EXPECT_EQ(page.find("http://"), std::string::npos);
    EXPECT_EQ(page.find("https://"), std::string::npos);
    for (const auto& src : values_after(page, "src=\"", '"'))
        EXPECT_EQ(src.rfind("figures/", 0), 0u) << src;
    EXPECT_EQ(page.find("<link"), std::string::npos);
    EXPECT_EQ(page.find("@import"), std::string::npos);
    EXPECT_NE(page.find("content=\"default-src 'none'; img-src 'self' file:;"), std::string::npos);
}

TEST_F(HtmlReport, ColoursTheAlgorithmsAsTheFiguresDo) {
    write_file(
        dir_ / "figures" / "styles.csv",
        "algorithm,label,colour,marker,linestyle\ntlbo,tlbo,#ff7f0e,s,--\nitlbo,x,red;}</style>,o,-\n");
    const std::string page = render_html_report(content_);
    EXPECT_NE(page.find("<span class=\"swatch\" style=\"background:#ff7f0e\"></span>tlbo"),
              std::string::npos);
    EXPECT_EQ(page.find("red;}"), std::string::npos); // not a plain colour: left out
}

TEST_F(HtmlReport, IsTheSameBytesWhenWrittenTwice) {
    const fs::path first = write_html_report(dir_, content_);
    EXPECT_EQ(first, dir_ / "index.html");
    const std::string once = read_text(first);
    write_html_report(dir_, content_);
    EXPECT_EQ(read_text(dir_ / "index.html"), once);
    EXPECT_EQ(once, render_html_report(content_));
    EXPECT_GT(once.size(), 1000u);
}

TEST_F(HtmlReport, SaysWhyTheFiguresAreMissing) {
    HtmlReportContent content = content_;
    content.budgets[0].directory = dir_ / "elsewhere"; // no figures/ folder
    content.budgets[0].figures_note = "figures skipped: no Python with matplotlib found";
    std::string page = render_html_report(content);
    EXPECT_EQ(count(page, "<img "), 0u);
    EXPECT_EQ(count(page, "No figures in this report: figures skipped: no Python with matplotlib found."),
              1u);
    content.budgets[0].figures_note.clear();
    page = render_html_report(content);
    EXPECT_NE(page.find("No figures in this report: figures/ holds no PNG file"), std::string::npos);

    // --no-figures with figures of an earlier report: shown, and said to be earlier.
    content = content_;
    content.budgets[0].figures_note = "the figures were not drawn (--no-figures)";
    content.budgets[0].figures_current = false;
    page = render_html_report(content);
    EXPECT_EQ(count(page, "<img "), 3u);
    EXPECT_NE(page.find("The figures were not drawn (--no-figures)."), std::string::npos);
    EXPECT_NE(page.find("from an earlier report"), std::string::npos);
}

TEST_F(HtmlReport, GivesEachBudgetAPageLinkedFromTheVerdict) {
    HtmlReportContent content = content_;
    content.budgets[0].folder = "iterations_150";
    fs::create_directories(dir_ / "iterations_150");
    fs::rename(dir_ / "figures", dir_ / "iterations_150" / "figures");
    content.budgets[0].directory = dir_ / "iterations_150";
    HtmlBudgetSection second = content.budgets[0];
    second.budget = "evaluations=15050";
    second.folder = "evaluations_15050";
    second.directory = dir_ / "none";
    content.budgets.push_back(second);
    write_file(dir_ / "budget_stale.html", "an earlier report's page");
    write_html_report(dir_, content);
    EXPECT_FALSE(fs::exists(dir_ / "budget_stale.html"));
    const std::vector<HtmlPage> pages = render_html_pages(content);
    ASSERT_EQ(pages.size(), 3u);
    EXPECT_EQ(pages[1].file, "budget_iterations_150.html");
    EXPECT_EQ(pages[2].file, "budget_evaluations_15050.html");
    const std::string& index = pages[0].text;
    EXPECT_EQ(count(index, "<table"), 2u); // the verdicts; the tables are on the budgets' pages
    EXPECT_EQ(count(index, "id=\"b-iterations_150-verdict\""), 1u);
    EXPECT_NE(index.find("<a href=\"budget_evaluations_15050.html\">"), std::string::npos);
    EXPECT_NE(index.find("src=\"iterations_150/figures/final_values_sphere_dim_2.png\""), std::string::npos);
    EXPECT_EQ(index.find("ecdf_targets"), std::string::npos); // not a key figure
    EXPECT_EQ(count(pages[1].text, "<table"), 2u);
    EXPECT_EQ(count(pages[1].text, "<img "), 3u);
    EXPECT_NE(pages[1].text.find("<a href=\"index.html\">"), std::string::npos);
    for (const auto& page : pages) {
        std::multiset<std::string> ids;
        for (const auto& id : values_after(page.text, " id=\"", '"'))
            ids.insert(id);
        for (const auto& id : ids)
            EXPECT_EQ(ids.count(id), 1u) << page.file << ": id \"" << id << "\" is not unique";
        for (const auto& href : values_after(page.text, "href=\"", '"')) {
            if (href[0] == '#')
                EXPECT_EQ(ids.count(href.substr(1)), 1u) << page.file << ": " << href;
            else // another page, or a figure's PDF beside its PNG
                EXPECT_TRUE(fs::exists(dir_ / href) || href.find("/figures/") != std::string::npos)
                    << page.file << ": " << href;
        }
        for (const auto& src : values_after(page.text, "src=\"", '"'))
            EXPECT_TRUE(fs::exists(dir_ / src)) << page.file << ": " << src;
    }
}

TEST(HtmlReportUrl, IsAbsoluteAndPercentEncoded) {
    EXPECT_EQ(file_url("/tmp/a b/index.html"), "file:///tmp/a%20b/index.html");
    EXPECT_EQ(file_url("/tmp/x/../r\xc3\xa9/#1.html"), "file:///tmp/r%C3%A9/%231.html");
    EXPECT_EQ(file_url("rel/index.html").rfind("file:///", 0), 0u);
}

RunRecord html_run(const std::string& algorithm, std::int64_t index, std::int64_t id) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = algorithm;
    r.problem = "sphere:dim=2";
    r.budget = "iterations=2";
    r.run_index = index;
    r.seed = static_cast<std::uint64_t>(100 + index);
    r.best_f = (algorithm == "tlbo" ? 2e-3 : 1e-3) * static_cast<double>(index + 1);
    r.f_opt = 0.0;
    r.evaluations = 30;
    r.iterations = 2;
    r.best_x = {0.01, -0.02};
    for (std::int64_t it = 0; it <= 2; ++it)
        r.curve.push_back({it, 10 * (it + 1), r.best_f * static_cast<double>(3 - it), {}});
    r.checkpoints = {{10, r.best_f * 3}, {30, r.best_f}};
    return r;
}

TEST(HtmlReportOfAStudy, BuildReportWritesOnePageWithEveryTable) {
    const fs::path dir = test_support::fresh_temporary_path("mhb_html_report_", "study");
    {
        StudyWriter writer(dir, "algorithms = itlbo tlbo\n", "version = 0.1.0\nthreads = 1\n", {}, false);
        std::int64_t id = 0;
        for (const char* algorithm : {"itlbo", "tlbo"})
            for (std::int64_t i = 0; i < 4; ++i)
                writer.append(html_run(algorithm, i, id++), 0.01);
        writer.finish();
    }
    ReportOptions options;
    options.figures = false;
    std::ostringstream console;
    const ReportOutcome outcome = build_report(load_study(dir), options, console);
    EXPECT_EQ(outcome.html, dir / "report" / "index.html");
    const std::string page = read_text(outcome.html);
    std::size_t tables = 0; // one .md file per table, beside report.md and the data dictionary README.md
    for (const auto& entry : fs::directory_iterator(dir / "report")) {
        const auto name = entry.path().filename();
        tables += entry.path().extension() == ".md" && name != "report.md" && name != "README.md" ? 1U : 0U;
    }
    EXPECT_GE(tables, 3u);                        // summary, tests, comparison at least
    EXPECT_EQ(count(page, "<table"), tables + 1); // and the verdict of its one problem
    EXPECT_NE(page.find("No figures in this report: the figures were not drawn (--no-figures)."),
              std::string::npos);
    EXPECT_NE(console.str().find("HTML report (verdict first): " + outcome.html.string()), std::string::npos);
    EXPECT_NE(console.str().find(file_url(outcome.html)), std::string::npos);
    // Rebuilt by every report, to the same bytes.
    std::ostringstream again;
    build_report(load_study(dir), options, again);
    EXPECT_EQ(read_text(outcome.html), page);
}

} // namespace
} // namespace mhb
