// The report as web pages: report/index.html opens with the verdict of every budget (who won, as
// tables whose algorithm names wear their figures' colours) and the key figures of each problem
// (convergence and final values), then, on a small study, every table and figure, and the study's
// metadata (context.ini, study.ini) last. A study with several budgets, or too many table rows for
// one page, gets a page per budget (budget_<slug>.html: its tables and all its figures) linked
// from index.html, so that no page grows with the study beyond its tables. Figures are images
// (figures/NAME.png, lazily loaded, each linking to its PDF), never inlined; nothing else is
// loaded (no CSS, script or font from elsewhere: the Content-Security-Policy allows images of the
// report only). The same inputs give the same bytes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "results/table_model/table.hpp" // a renderer sees tables, never runs

namespace mhb {

struct HtmlBudgetSection {
    std::string budget;              // as recorded, e.g. "iterations=150"; empty: not recorded
    std::string folder;              // its report folder under the page's ("" when the layout is flat)
    std::filesystem::path directory; // that folder on disk: its figures/*.svg are inlined
    std::vector<Table> tables;
    std::vector<Table> verdict; // the verdict's tables (results/tables/verdict_tables.hpp), shown first
    // What the reader must know about the figures (skipped, failed, interrupted, not drawn with
    // --no-figures); empty when they were drawn without trouble.
    std::string figures_note;
    // False when the figures were not drawn by this report: PNG files found are an earlier report's.
    bool figures_current = true;
};

struct HtmlReportContent {
    std::string study;        // the study directory, as the page names it
    std::string context_text; // context.ini: version, commit, compiler, threads, date, command
    std::string study_text;   // study.ini: the study as run
    std::vector<HtmlBudgetSection> budgets;
    // Past this many table rows in all (about 0.4 kB each) every budget gets a page of its own, as
    // with several budgets: index.html keeps the verdict and the key figures.
    std::size_t rows_on_one_page = 1500;
    // index.html shows the key figures of at most this many problems per budget; the budget's page
    // shows them all.
    std::size_t key_figure_problems = 8;
};

struct HtmlPage {
    std::string file; // "index.html", "budget_iterations_150.html"
    std::string text;
};

// The pages, index.html first. Lists the PNG files of each section's figures/ folder and reads its
// styles.csv (html_figures.hpp).
std::vector<HtmlPage> render_html_pages(const HtmlReportContent& content);
// index.html alone.
std::string render_html_report(const HtmlReportContent& content);

// Writes every page into `dir` atomically, removes the budget pages of an earlier report that this
// one has not, and returns index.html's path. Throws std::runtime_error when a page cannot be written.
std::filesystem::path write_html_report(const std::filesystem::path& dir, const HtmlReportContent& content);

// file:///absolute/path with every byte outside [A-Za-z0-9-._~/] percent-encoded.
std::string file_url(const std::filesystem::path& path);

} // namespace mhb
