// The HTML report (index.html): every table and caption, escaped; the figures' SVG files inlined
// with their prolog dropped and ids unique on the page; nothing that would load from outside the
// page; the same bytes when written twice; and a clear note where figures are missing.
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

// A matplotlib-like SVG: prolog, DOCTYPE, metadata, and the ids matplotlib gives every figure.
std::string figure_svg(const std::string& title) {
    return "<?xml version=\"1.0\" encoding=\"utf-8\" standalone=\"no\"?>\n"
           "<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\"\n"
           "  \"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n"
           "<svg xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"100pt\" height=\"50pt\" "
           "viewBox=\"0 0 100 50\" xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\">\n <title>" +
           title +
           "</title>\n <metadata><rdf:RDF xmlns:dc=\"http://purl.org/dc/elements/1.1/\"/></metadata>\n"
           " <g id=\"figure_1\"><g id=\"axes_1\">\n"
           "  <path d=\"M 0 0 L 9 9\" clip-path=\"url(#p3c2b)\"/>\n"
           "  <use xlink:href=\"#m5e1\" x=\"1\" y=\"2\"/>\n"
           " </g></g>\n"
           " <defs><clipPath id=\"p3c2b\"><rect width=\"9\"/></clipPath><path id=\"m5e1\" d=\"M 0 "
           "0\"/></defs>\n"
           "</svg>\n";
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
        write_file(dir_ / "figures" / "convergence_iteration_sphere_dim_2.svg", figure_svg("conv"));
        write_file(dir_ / "figures" / "final_values_sphere_dim_2.svg", figure_svg("final"));
        write_file(dir_ / "figures" / "final_values_sphere_dim_2.png", "not inlined");
        write_file(dir_ / "figures" / ".final_values_sphere_dim_2.svg.tmp-123", "a drawing in progress");

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
    EXPECT_EQ(count(page, "<table"), 2u);
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

TEST_F(HtmlReport, InlinesEverySvgFigureWithoutPrologAndWithIdsUniqueOnThePage) {
    const std::string page = render_html_report(content_);
    EXPECT_EQ(count(page, "<svg"), 2u); // the two .svg files; not the PNG, not the temporary file
    EXPECT_EQ(page.find("<?xml"), std::string::npos);
    EXPECT_EQ(page.find("<!DOCTYPE svg"), std::string::npos);
    EXPECT_EQ(page.find("<metadata"), std::string::npos);
    EXPECT_EQ(page.find("drawing in progress"), std::string::npos);
    EXPECT_NE(page.find("<title>conv</title>"), std::string::npos);
    EXPECT_NE(page.find("<title>final</title>"), std::string::npos);
    EXPECT_LT(page.find("Convergence by iteration</h3>"), page.find("Final values</h3>"));

    std::multiset<std::string> ids;
    for (const auto& id : values_after(page, " id=\"", '"'))
        ids.insert(id);
    for (const auto& id : ids)
        EXPECT_EQ(ids.count(id), 1u) << "id \"" << id << "\" is not unique";
    EXPECT_EQ(ids.count("figure_1"), 0u);
    // Both figures had clip path "p3c2b": each now points to its own.
    const auto urls = values_after(page, "url(#", ')');
    ASSERT_EQ(urls.size(), 2u);
    EXPECT_NE(urls[0], urls[1]);
    for (const auto& target : urls)
        EXPECT_EQ(ids.count(target), 1u) << "url(#" << target << ") points to no id";
    for (const auto& href : values_after(page, "href=\"", '"')) {
        ASSERT_FALSE(href.empty());
        ASSERT_EQ(href[0], '#') << href;
        EXPECT_EQ(ids.count(href.substr(1)), 1u) << "href=\"" << href << "\" points to no id";
    }
}

TEST_F(HtmlReport, LoadsNothingFromOutsideThePage) {
    const std::string page = render_html_report(content_);
    EXPECT_EQ(page.find("http://"), std::string::npos);
    EXPECT_EQ(page.find("https://"), std::string::npos);
    EXPECT_EQ(page.find("src="), std::string::npos);
    EXPECT_EQ(page.find("<link"), std::string::npos);
    EXPECT_EQ(page.find("@import"), std::string::npos);
    for (const auto& href : values_after(page, "href=\"", '"'))
        EXPECT_EQ(href.rfind('#', 0), 0u) << href;
    EXPECT_NE(page.find("content=\"default-src 'none';"), std::string::npos);
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
    EXPECT_EQ(count(page, "<svg"), 0u);
    EXPECT_NE(page.find("No figures in this report: figures skipped: no Python with matplotlib found."),
              std::string::npos);
    content.budgets[0].figures_note.clear();
    page = render_html_report(content);
    EXPECT_NE(page.find("No figures in this report: figures/ holds no SVG file"), std::string::npos);

    // --no-figures with figures of an earlier report: shown, and said to be earlier.
    content = content_;
    content.budgets[0].figures_note = "the figures were not drawn (--no-figures)";
    content.budgets[0].figures_current = false;
    page = render_html_report(content);
    EXPECT_EQ(count(page, "<svg"), 2u);
    EXPECT_NE(page.find("The figures were not drawn (--no-figures)."), std::string::npos);
    EXPECT_NE(page.find("from an earlier report"), std::string::npos);
}

TEST_F(HtmlReport, NamesTheFiguresPastTheSizeLimitAndThoseThatCannotBeRead) {
    HtmlReportContent content = content_;
    content.max_inline_svg_bytes = figure_svg("conv").size(); // room for one
    std::string page = render_html_report(content);
    EXPECT_EQ(count(page, "<svg"), 1u);
    EXPECT_NE(page.find("1 figure not inlined"), std::string::npos);
    EXPECT_NE(page.find("final_values_sphere_dim_2"), std::string::npos);

    write_file(dir_ / "figures" / "zz_broken.svg", "<?xml version=\"1.0\"?>\n<svg width=\"1\"");
    page = render_html_report(content_);
    EXPECT_EQ(count(page, "<svg"), 2u);
    EXPECT_NE(page.find("figures/zz_broken.svg could not be inlined: no &lt;svg&gt; element"),
              std::string::npos);
}

TEST_F(HtmlReport, GivesEachBudgetItsOwnSection) {
    HtmlReportContent content = content_;
    content.budgets[0].folder = "iterations_150";
    HtmlBudgetSection second = content.budgets[0];
    second.budget = "evaluations=15050";
    second.folder = "evaluations_15050";
    second.directory = dir_ / "none";
    content.budgets.push_back(second);
    const std::string page = render_html_report(content);
    EXPECT_EQ(count(page, "<table"), 4u);
    EXPECT_EQ(count(page, "<svg"), 2u);
    EXPECT_NE(page.find("<section class=\"budget\" id=\"b-iterations_150\">"), std::string::npos);
    EXPECT_NE(page.find("<section class=\"budget\" id=\"b-evaluations_15050\">"), std::string::npos);
    EXPECT_NE(page.find("id=\"b-evaluations_15050-t-summary\""), std::string::npos);
    EXPECT_NE(page.find("<h2>Budget evaluations=15050 (files in evaluations_15050/)</h2>"),
              std::string::npos);
    std::multiset<std::string> ids;
    for (const auto& id : values_after(page, " id=\"", '"'))
        ids.insert(id);
    for (const auto& id : ids)
        EXPECT_EQ(ids.count(id), 1u) << "id \"" << id << "\" is not unique";
    for (const auto& href : values_after(page, "href=\"", '"'))
        EXPECT_EQ(ids.count(href.substr(1)), 1u) << href;
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
    EXPECT_GE(tables, 3u); // summary, tests, comparison at least
    EXPECT_EQ(count(page, "<table"), tables);
    EXPECT_NE(page.find("No figures in this report: the figures were not drawn (--no-figures)."),
              std::string::npos);
    EXPECT_NE(console.str().find("HTML report (one self-contained page): " + outcome.html.string()),
              std::string::npos);
    EXPECT_NE(console.str().find(file_url(outcome.html)), std::string::npos);
    // Rebuilt by every report, to the same bytes.
    std::ostringstream again;
    build_report(load_study(dir), options, again);
    EXPECT_EQ(read_text(outcome.html), page);
}

} // namespace
} // namespace mhb
