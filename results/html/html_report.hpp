// The report as one self-contained web page, report/index.html: the study's context, a table of
// contents, every table of the report (sortable by a click on a header; plain HTML tables without
// JavaScript) and every figure inlined as SVG (from figures/*.svg, drawn by scripts/plot_study.py).
// It loads nothing: no network, no other file (its Content-Security-Policy forbids any fetch), so
// it can be mailed or archived alone. A study with several budgets gets one page with a section per
// budget. The same inputs give the same bytes.
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
    // What the reader must know about the figures (skipped, failed, interrupted, not drawn with
    // --no-figures); empty when they were drawn without trouble.
    std::string figures_note;
    // False when the figures were not drawn by this report: SVG files found are an earlier report's.
    bool figures_current = true;
};

struct HtmlReportContent {
    std::string study;        // the study directory, as the page names it
    std::string context_text; // context.ini: version, commit, compiler, threads, date, command
    std::string study_text;   // study.ini: the study as run
    std::vector<HtmlBudgetSection> budgets;
    // Past this many bytes of SVG the remaining figures are named instead of inlined (a study of
    // thousands of problems would otherwise make a page no browser opens).
    std::size_t max_inline_svg_bytes = std::size_t{64} << 20;
};

// The page. Reads the SVG files of each section's figures/ folder; one that cannot be read or holds
// no <svg> element is named on the page instead.
std::string render_html_report(const HtmlReportContent& content);

// Writes `dir`/index.html atomically and returns its path. Throws std::runtime_error when it
// cannot be written.
std::filesystem::path write_html_report(const std::filesystem::path& dir, const HtmlReportContent& content);

// file:///absolute/path with every byte outside [A-Za-z0-9-._~/] percent-encoded.
std::string file_url(const std::filesystem::path& path);

} // namespace mhb
