#include "results/html/html_report.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <system_error>

#include "results/html/html_escape.hpp"
#include "results/html/html_figures.hpp"
#include "results/html/html_page_assets.hpp"
#include "results/html/html_table.hpp"
#include "results/store/context_ini.hpp" // the page shows where the study was run
#include "results/store/csv.hpp"         // CSV as the store writes it, for every room
#include "results/store/study_index.hpp" // budget_slug: a budget page is named as its folder

namespace mhb {

namespace fs = std::filesystem;

namespace {

std::string heading(int level, const std::string& text, const std::string& id = "") {
    const std::string h = std::to_string(level);
    return "<h" + h + (id.empty() ? "" : " id=\"" + id + "\"") + ">" + html_escape(text) + "</h" + h + ">\n";
}

std::string note(const std::string& text) {
    return "<p class=\"note\">" + html_escape(text) + "</p>\n";
}

// `text` as a sentence: a capital first letter and a full stop.
std::string sentence(std::string text, bool capital = true) {
    if (capital && !text.empty() && text[0] >= 'a' && text[0] <= 'z')
        text[0] = static_cast<char>(text[0] - 'a' + 'A');
    if (!text.empty() && text.back() != '.')
        text += '.';
    return text;
}

std::string context_section(const HtmlReportContent& content) {
    std::string out = "<section id=\"context\">\n" + heading(2, "Study context");
    // The facts a reader checks first, then both files whole.
    const std::pair<const char*, const char*> shown[] = {{"version", "mhbench version"},
                                                         {"git_commit", "Commit"},
                                                         {"git_dirty_at_build", "Uncommitted changes"},
                                                         {"compiler", "Compiler"},
                                                         {"build_type", "Build"},
                                                         {"threads", "Threads"},
                                                         {"cpu", "CPU"},
                                                         {"date_utc", "Date (UTC)"},
                                                         {"command", "Command"}};
    const auto pairs = context_entries(content.context_text);
    std::string facts;
    for (const auto& [key, label] : shown)
        for (const auto& [k, v] : pairs)
            if (k == key) {
                facts += "<dt>" + html_escape(label) + "</dt><dd>" + html_escape(v) + "</dd>\n";
                break;
            }
    // The history of a resumed study (context.ini's "session" lines): its first and latest session.
    std::vector<std::string> sessions;
    for (const auto& [k, v] : pairs)
        if (k == "session")
            sessions.push_back(v);
    if (sessions.size() > 1)
        facts += "<dt>First session</dt><dd>" + html_escape(sessions.front()) +
                 "</dd>\n<dt>Latest session (of " + std::to_string(sessions.size()) + ")</dt><dd>" +
                 html_escape(sessions.back()) + "</dd>\n";
    out += "<dl class=\"context\">\n<dt>Study directory</dt><dd><code>" + html_escape(content.study) +
           "</code></dd>\n" + facts + "</dl>\n";
    out += heading(3, "context.ini");
    out += content.context_text.empty() ? note("This study has no context.ini.")
                                        : "<pre>" + html_escape(content.context_text) + "</pre>\n";
    out += heading(3, "study.ini (the study as run; mhbench run --study-file re-runs it)");
    out += content.study_text.empty() ? note("This study has no study.ini.")
                                      : "<pre>" + html_escape(content.study_text) + "</pre>\n";
    return out + "</section>\n";
}

// Where one budget's parts live: the page holding its tables and figures, its ids' prefix, and the
// folder of its figures relative to the pages.
struct BudgetPlace {
    std::string page;   // "index.html" or "budget_<slug>.html"
    std::string prefix; // of its ids on index.html ("" with one budget)
    std::string folder; // its report folder under the pages' ("" when flat)
};

std::string budget_name(const HtmlBudgetSection& budget) {
    return budget.budget.empty() ? std::string("unspecified") : budget.budget;
}

bool split_into_pages(const HtmlReportContent& content) {
    std::size_t rows = 0;
    for (const auto& budget : content.budgets)
        for (const auto& t : budget.tables)
            rows += t.rows.size();
    return content.budgets.size() > 1 || rows > content.rows_on_one_page;
}

BudgetPlace place_of(const HtmlBudgetSection& budget, bool several, bool split) {
    const std::string slug = budget.folder.empty() ? budget_slug(budget.budget) : budget.folder;
    return {split ? "budget_" + slug + ".html" : "index.html", several ? "b-" + html_anchor(slug) + "-" : "",
            budget.folder};
}

// What the page says when figures/ holds no PNG file, or about the figures it shows.
std::string figures_notes(const HtmlBudgetSection& budget, bool any) {
    if (!any)
        return note("No figures in this report: " +
                    sentence(budget.figures_note.empty()
                                 ? "figures/ holds no PNG file (run mhbench report again with matplotlib "
                                   "installed: apt install python3-matplotlib)"
                                 : budget.figures_note,
                             false));
    std::string out;
    if (!budget.figures_note.empty())
        out += note(sentence(budget.figures_note));
    if (!budget.figures_current)
        out += note("The figures below are from an earlier report of this folder: they may not match the "
                    "tables.");
    return out;
}

// Every figure of a budget, grouped by kind; `key` false leaves out the key figures (shown above
// them on the same page). The kinds shown go to `kinds` for the contents.
std::string figures_by_kind(const HtmlBudgetSection& budget, const BudgetPlace& place, int level, bool key,
                            std::vector<std::size_t>& kinds) {
    const std::vector<std::string> names = png_figures(budget.directory);
    // Below the key figures on the same page, what they said of missing figures stands.
    std::string out = key || !names.empty() ? figures_notes(budget, !names.empty()) : "";
    for (std::size_t k = 0; k < figure_kinds().size(); ++k) {
        std::string group;
        for (const auto& name : names)
            if (figure_kind_of(name) == k && (key || !key_figure(name)))
                group += figure_html(place.folder, name, place.prefix + "f-" + html_anchor(name));
        if (group.empty())
            continue;
        kinds.push_back(k);
        const FigureKind& kind = figure_kinds()[k];
        out += "<section class=\"figures\" id=\"" + place.prefix + "g-" + std::to_string(k) + "\">\n" +
               heading(level, kind.heading);
        if (*kind.description != '\0')
            out += "<p class=\"caption\">" + html_escape(kind.description) + "</p>\n";
        out += "<div class=\"grid\">\n" + group + "</div>\n</section>\n";
    }
    return out;
}

// The key figures of each problem (convergence, final values) side by side, for at most `problems`
// problems; the rest are named as being on the budget's page.
std::string key_figures(const HtmlBudgetSection& budget, const BudgetPlace& place, std::size_t problems) {
    std::vector<std::string> order; // problems (figure-name suffixes) as the file names sort them
    std::map<std::string, std::vector<std::string>> by_problem;
    for (const auto& name : png_figures(budget.directory)) {
        if (!key_figure(name))
            continue;
        const std::string problem =
            name.substr(std::string(figure_kinds()[figure_kind_of(name)].prefix).size());
        if (by_problem[problem].empty())
            order.push_back(problem);
        by_problem[problem].push_back(name);
    }
    if (order.empty())
        return figures_notes(budget, false);
    std::string out = figures_notes(budget, true);
    for (std::size_t i = 0; i < order.size() && i < problems; ++i) {
        out += "<div class=\"grid\">\n";
        for (const auto& name : by_problem[order[i]]) // in file-name order: convergence, then final values
            out += figure_html(place.folder, name, place.prefix + "k-" + html_anchor(name));
        out += "</div>\n";
    }
    if (order.size() > problems)
        out += note("The key figures of " + std::to_string(order.size() - problems) +
                    " more problems are on " + "the budget's page, with every other figure.");
    return out;
}

std::string title_without_budget(const HtmlBudgetSection& budget, std::string title) {
    const std::string suffix = " [budget " + budget.budget + "]";
    if (!budget.budget.empty() && title.size() > suffix.size() &&
        title.compare(title.size() - suffix.size(), suffix.size(), suffix) == 0)
        title.resize(title.size() - suffix.size());
    return title;
}

std::string toc_tables(const HtmlBudgetSection& budget, const BudgetPlace& place) {
    std::string out = "<ul>\n";
    for (const auto& t : budget.tables)
        out += "<li><a href=\"#" + place.prefix + "t-" + html_anchor(t.id) + "\">" +
               html_escape(title_without_budget(budget, t.title)) + "</a></li>\n";
    return out + "</ul>\n";
}

std::string toc_figures(const std::vector<std::size_t>& kinds, const BudgetPlace& place) {
    if (kinds.empty())
        return "";
    std::string out = "<ul>\n";
    for (std::size_t k : kinds)
        out += "<li><a href=\"#" + place.prefix + "g-" + std::to_string(k) + "\">" +
               html_escape(figure_kinds()[k].heading) + "</a></li>\n";
    return out + "</ul>\n";
}

// A budget's tables and figures (every figure when `key` is true), and their lines of the contents.
struct Details {
    std::string html;
    std::string toc;
};

Details budget_details(const HtmlBudgetSection& budget, const BudgetPlace& place, int level, bool key) {
    const std::map<std::string, std::string> colours = figure_colours(budget.directory);
    std::string tables;
    for (const auto& t : budget.tables)
        tables += render_html_table(t, place.prefix + "t-" + html_anchor(t.id), level + 1, colours);
    if (budget.tables.empty())
        tables = note("This budget has no table.");
    std::vector<std::size_t> kinds;
    const std::string figures = figures_by_kind(budget, place, level + 1, key, kinds);
    const std::string tables_id = place.prefix + "tables";
    const std::string figures_id = place.prefix + "figures";
    return {"<section id=\"" + tables_id + "\">\n" + heading(level, "Tables") + tables +
                "</section>\n<section id=\"" + figures_id + "\">\n" +
                heading(level, key ? "Figures" : "Other figures") + figures + "</section>\n",
            "<li><a href=\"#" + tables_id + "\">Tables</a>\n" + toc_tables(budget, place) +
                "</li>\n<li><a href=\"#" + figures_id + "\">" + (key ? "Figures" : "Other figures") +
                "</a>\n" + toc_figures(kinds, place) + "</li>\n"};
}

// The verdict of a budget: its tables, algorithm names in their figures' colours.
std::string verdict_html(const HtmlBudgetSection& budget, const BudgetPlace& place, int level) {
    const std::map<std::string, std::string> colours = figure_colours(budget.directory);
    std::string out;
    for (const auto& t : budget.verdict)
        out += render_html_table(t, place.prefix + "v-" + html_anchor(t.id), level, colours);
    if (budget.verdict.empty())
        out = note("No verdict: this budget has no successful run.");
    return out;
}

std::string page_head(const std::string& title) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
           // The page fetches nothing but the report's own images: styles and the script are inline.
           "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src 'self' file:; "
           "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n"
           "<meta name=\"generator\" content=\"mhbench report\">\n"
           "<title>" +
           html_escape(title) + "</title>\n<style>" + html_report_style() + "</style>\n</head>\n<body>\n";
}

std::string page_end() {
    return "<footer><p class=\"caption\">Written by <code>mhbench report</code> from the study directory "
           "alone; "
           "the tables are also in Markdown, LaTeX and CSV beside this page. Click a column header to sort "
           "(again: descending; a third time: the original order).</p></footer>\n<script>" +
           std::string(html_report_script()) + "</script>\n</body>\n</html>\n";
}

// index.html: the verdict and key figures of every budget, then (one page) the tables and the other
// figures or (several pages) links to the budgets' pages, and the study's metadata last.
std::string index_page(const HtmlReportContent& content, const std::vector<BudgetPlace>& places, bool split) {
    const bool several = content.budgets.size() > 1;
    const int level = several ? 3 : 2;
    std::string verdicts;
    std::string figures;
    std::string details;
    std::string toc_verdict;
    std::string toc_details;
    for (std::size_t b = 0; b < content.budgets.size(); ++b) {
        const HtmlBudgetSection& budget = content.budgets[b];
        const BudgetPlace& place = places[b];
        const std::string name = "Budget " + budget_name(budget);
        const std::string link = split
                                     ? "<p class=\"pages\"><a href=\"" + html_escape(place.page) +
                                           "\">Every table and figure of " + html_escape(name) + "</a></p>\n"
                                     : "";
        verdicts += (several ? heading(level, name, place.prefix + "verdict") : "") +
                    verdict_html(budget, place, level + 1) + link;
        figures += (several ? heading(level, name, place.prefix + "key") : "") +
                   key_figures(budget, place, split ? content.key_figure_problems : SIZE_MAX);
        if (several)
            toc_verdict +=
                "<li><a href=\"#" + place.prefix + "verdict\">" + html_escape(name) + "</a></li>\n";
        if (split) {
            toc_details += "<li><a href=\"" + html_escape(place.page) + "\">" + html_escape(name) +
                           ": every table and figure</a></li>\n";
        } else {
            const Details d = budget_details(budget, place, 2, false);
            details += d.html;
            toc_details += d.toc;
        }
    }
    std::string page = page_head("mhbench report: " + content.study);
    page += "<header>\n<h1>mhbench report: " + html_escape(content.study) + "</h1>\n";
    if (several)
        page += "<p class=\"caption\">" + std::to_string(content.budgets.size()) +
                " budgets, each its own experiment: a verdict each, and a page each with its tables and "
                "figures.</p>\n";
    // The verdict comes before the contents: it is what the page is opened for.
    const std::string nav = "<nav class=\"toc\" aria-label=\"Contents\">\n" + heading(2, "Contents") +
                            "<ul>\n<li><a href=\"#verdict\">Verdict</a>" +
                            (several ? "\n<ul>\n" + toc_verdict + "</ul>\n" : "") +
                            "</li>\n<li><a href=\"#key-figures\">Key figures</a></li>\n" + toc_details +
                            "<li><a href=\"#context\">Study context</a></li>\n</ul>\n</nav>\n";
    page += "</header>\n<main>\n<section id=\"verdict\">\n" + heading(2, "Verdict") +
            "<p class=\"caption\">Who won: per problem the algorithms ranked by median final value, each "
            "tested against the best; across problems their mean ranks; for a factorial design what each "
            "component does. The full tables follow" +
            (split ? std::string(" on each budget's page.") : std::string(" below.")) + "</p>\n" + verdicts +
            "</section>\n" + nav + "<section id=\"key-figures\">\n" + heading(2, "Key figures") +
            "<p class=\"caption\">Per problem: convergence (median and interquartile band) and the final "
            "values' box plot. Each image links to its PDF.</p>\n" +
            figures + "</section>\n";
    if (split) {
        page += "<section id=\"pages\">\n" + heading(2, "Tables and figures") + "<ul class=\"pages\">\n" +
                toc_details + "</ul>\n</section>\n";
    } else {
        page += details;
    }
    return page + context_section(content) + "</main>\n" + page_end();
}

// budget_<slug>.html: one budget's tables and every figure, with the way back to the verdict.
std::string budget_page(const HtmlReportContent& content, const HtmlBudgetSection& budget,
                        const BudgetPlace& place) {
    const BudgetPlace own{place.page, "", place.folder};
    const Details d = budget_details(budget, own, 2, true);
    const std::string name = "Budget " + budget_name(budget);
    std::string page = page_head("mhbench report: " + content.study + ", " + name);
    page += "<header>\n<h1>mhbench report: " + html_escape(content.study) + "</h1>\n<p class=\"pages\">" +
            html_escape(name) +
            (budget.folder.empty() ? "" : " (files in " + html_escape(budget.folder) + "/)") +
            ". <a href=\"index.html\">The verdict and key figures of every budget</a>.</p>\n</header>\n" +
            "<nav class=\"toc\" aria-label=\"Contents\">\n" + heading(2, "Contents") + "<ul>\n" + d.toc +
            "</ul>\n</nav>\n<main>\n" + d.html + "</main>\n";
    return page + page_end();
}

} // namespace

std::vector<HtmlPage> render_html_pages(const HtmlReportContent& content) {
    const bool split = split_into_pages(content);
    std::vector<BudgetPlace> places;
    for (const auto& budget : content.budgets)
        places.push_back(place_of(budget, content.budgets.size() > 1, split));
    std::vector<HtmlPage> pages = {{"index.html", index_page(content, places, split)}};
    if (split)
        for (std::size_t b = 0; b < content.budgets.size(); ++b)
            pages.push_back({places[b].page, budget_page(content, content.budgets[b], places[b])});
    return pages;
}

std::string render_html_report(const HtmlReportContent& content) {
    return render_html_pages(content).front().text;
}

fs::path write_html_report(const fs::path& dir, const HtmlReportContent& content) {
    const std::vector<HtmlPage> pages = render_html_pages(content);
    std::set<std::string> written;
    for (const auto& page : pages) {
        write_file_atomically(dir / page.file, page.text);
        written.insert(page.file);
    }
    // An earlier report's budget pages that this one has not would show stale tables.
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string file = it->path().filename().string();
        if (file.rfind("budget_", 0) == 0 && file.size() > 5 &&
            file.compare(file.size() - 5, 5, ".html") == 0 && written.count(file) == 0)
            fs::remove(it->path(), ec);
    }
    return dir / "index.html";
}

std::string file_url(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    if (ec)
        absolute = path;
    const std::string text = absolute.lexically_normal().string();
    std::string out = "file://";
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                           c == '-' || c == '.' || c == '_' || c == '~' || c == '/';
        if (plain) {
            out += static_cast<char>(c);
        } else {
            char hex[4];
            std::snprintf(hex, sizeof hex, "%%%02X", static_cast<unsigned>(c));
            out += hex;
        }
    }
    return out;
}

} // namespace mhb
