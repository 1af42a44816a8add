#include "results/html/html_report.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <system_error>

#include "results/html/html_escape.hpp"
#include "results/html/html_page_assets.hpp"
#include "results/html/html_svg.hpp"
#include "results/html/html_table.hpp"
#include "results/store/context_ini.hpp" // the page shows where the study was run
#include "results/store/csv.hpp"         // CSV as the store writes it, for every room

namespace mhb {

namespace fs = std::filesystem;

namespace {

// The figures of plot_study.py by file-name prefix, in the order a reader wants them; a longer
// prefix comes before a shorter one it extends (ecdf_targets_ before ecdf_target_).
struct FigureKind {
    const char* prefix;
    const char* heading;
    const char* description;
};

constexpr FigureKind figure_kinds[] = {
    {"convergence_iteration_", "Convergence by iteration",
     "Median best-so-far f per iteration; the band is the interquartile range (order statistics, as "
     "meaningful on the log axis as on a linear one)."},
    {"convergence_evaluations_", "Convergence by evaluations",
     "Median best-so-far f against evaluations (log-log); the band is the interquartile range."},
    {"parameter_", "Identified parameters",
     "Mean best-so-far parameter per iteration (band: one standard deviation); dashed: the true value, "
     "dotted: the least-squares optimum."},
    {"final_values_", "Final values", "Box plots of the final best f of each algorithm's runs."},
    {"ecdf_targets_", "Fixed-target ECDFs",
     "Fraction of (run, target) pairs reached within a number of evaluations, over COCO's targets "
     "f - f* = 1e2 ... 1e-8."},
    {"ecdf_target_", "Runs that reached the study's target",
     "Fraction of runs that reached the study's target within a number of evaluations."},
    {"relative_gaps", "Relative gap to f* per problem",
     "Median relative gap (f - f*) / |f*| of the final values per problem (log axis, problems in the "
     "study's order), one line per algorithm: where the lines part, the optimisers stop being "
     "interchangeable."},
    {"critical_difference", "Critical difference",
     "Friedman average ranks across problems with the Nemenyi critical difference (Demsar 2006); a bar "
     "joins algorithms that do not differ significantly."},
    {"effects_overview_", "Effects of the components: overview",
     "Every main effect and two-way interaction of a 2^k on/off design, per problem (mean over blocks; "
     "negative: lower f, the component helps; hatched: not significant after Holm)."},
    {"effects_main_", "Main effects", "Mean response with each switch off and on."},
    {"effects_interaction_", "Two-way interactions",
     "Mean response of one switch off and on, one line per level of another."},
    {"", "Other figures", ""},
};

constexpr std::size_t figure_kind_count = sizeof(figure_kinds) / sizeof(figure_kinds[0]);

std::size_t kind_of(const std::string& name) {
    for (std::size_t k = 0; k < figure_kind_count; ++k)
        if (name.rfind(figure_kinds[k].prefix, 0) == 0)
            return k;
    return figure_kind_count - 1;
}

// The SVG files of `dir`/figures, by name (temporary files of a drawing in progress start with '.').
std::vector<std::string> svg_figures(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(dir / "figures", ec), end; !ec && it != end; it.increment(ec)) {
        const std::string file = it->path().filename().string();
        if (file.size() > 4 && file[0] != '.' && file.compare(file.size() - 4, 4, ".svg") == 0 &&
            it->is_regular_file(ec))
            names.push_back(file.substr(0, file.size() - 4));
    }
    std::sort(names.begin(), names.end());
    return names;
}

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

struct Anchors {
    std::string section; // the budget's section ("" when flat)
    std::string tables;
    std::string figures;
    std::string prefix; // of its tables and figures
};

Anchors anchors_of(const HtmlBudgetSection& budget, bool several) {
    if (!several)
        return {"", "tables", "figures", ""};
    const std::string b = "b-" + html_anchor(budget.folder.empty() ? budget.budget : budget.folder);
    return {b, b + "-tables", b + "-figures", b + "-"};
}

std::string budget_name(const HtmlBudgetSection& budget) {
    return budget.budget.empty() ? std::string("unspecified") : budget.budget;
}

// The figures of one section, grouped by kind; `inlined` counts SVG bytes of the whole page.
std::string figures_html(const HtmlBudgetSection& budget, const Anchors& anchors, int level,
                         std::size_t max_bytes, std::size_t& inlined, std::size_t& svg_counter,
                         std::vector<std::size_t>& kinds_present) {
    const std::vector<std::string> names = svg_figures(budget.directory);
    std::string out;
    if (names.empty()) {
        out += note("No figures in this report: " +
                    sentence(budget.figures_note.empty()
                                 ? "figures/ holds no SVG file (run mhbench report again with matplotlib "
                                   "installed: apt install python3-matplotlib)"
                                 : budget.figures_note,
                             false));
        return out;
    }
    if (!budget.figures_note.empty())
        out += note(sentence(budget.figures_note));
    if (!budget.figures_current)
        out += note("The figures below are from an earlier report of this folder: they may not match the "
                    "tables.");
    std::vector<std::string> left_out;
    for (std::size_t k = 0; k < figure_kind_count; ++k) {
        std::string group;
        for (const auto& name : names) {
            if (kind_of(name) != k)
                continue;
            const fs::path file = budget.directory / "figures" / (name + ".svg");
            const std::string anchor = anchors.prefix + "f-" + html_anchor(name);
            std::string svg;
            try {
                const std::string text = read_whole_file(file);
                if (inlined + text.size() > max_bytes) {
                    left_out.push_back(name);
                    continue;
                }
                svg = inline_svg(text, std::string("s").append(std::to_string(++svg_counter)), name);
                inlined += text.size();
            } catch (const std::exception& error) {
                group += "<figure id=\"" + anchor + "\">" +
                         note("figures/" + name + ".svg could not be inlined: " + error.what()) +
                         "</figure>\n";
                continue;
            }
            group += "<figure id=\"" + anchor + "\">\n" + svg + "\n<figcaption><code>figures/" +
                     html_escape(name) + ".svg</code> (.pdf and .png beside it)</figcaption>\n</figure>\n";
        }
        if (group.empty())
            continue;
        kinds_present.push_back(k);
        out += "<section class=\"figures\" id=\"" + anchors.prefix + "g-" + std::to_string(k) + "\">\n" +
               heading(level, figure_kinds[k].heading);
        if (*figure_kinds[k].description != '\0')
            out += "<p class=\"caption\">" + html_escape(figure_kinds[k].description) + "</p>\n";
        out += "<div class=\"grid\">\n" + group + "</div>\n</section>\n";
    }
    if (!left_out.empty()) {
        std::string list;
        for (std::size_t i = 0; i < left_out.size() && i < 10; ++i)
            list += (i ? ", " : "") + left_out[i];
        if (left_out.size() > 10)
            list += ", ...";
        out += note(std::to_string(left_out.size()) + " figure" + (left_out.size() == 1 ? "" : "s") +
                    " not inlined, the page would pass " + std::to_string(max_bytes >> 20) +
                    " MB of SVG: see figures/ in the report folder (" + list + ").");
    }
    return out;
}

std::string toc_tables(const HtmlBudgetSection& budget, const Anchors& anchors) {
    std::string out = "<ul>\n";
    // Within a budget's entry, " [budget X]" at the end of every title says nothing new.
    const std::string suffix = " [budget " + budget.budget + "]";
    for (const auto& t : budget.tables) {
        std::string title = t.title;
        if (!budget.budget.empty() && title.size() > suffix.size() &&
            title.compare(title.size() - suffix.size(), suffix.size(), suffix) == 0)
            title.resize(title.size() - suffix.size());
        out += "<li><a href=\"#" + anchors.prefix + "t-" + html_anchor(t.id) + "\">" + html_escape(title) +
               "</a></li>\n";
    }
    return out + "</ul>\n";
}

std::string toc_figures(const std::vector<std::size_t>& kinds, const Anchors& anchors) {
    if (kinds.empty())
        return "";
    std::string out = "<ul>\n";
    for (std::size_t k : kinds)
        out += "<li><a href=\"#" + anchors.prefix + "g-" + std::to_string(k) + "\">" +
               html_escape(figure_kinds[k].heading) + "</a></li>\n";
    return out + "</ul>\n";
}

} // namespace

std::string render_html_report(const HtmlReportContent& content) {
    const bool several = content.budgets.size() > 1;
    const int base = several ? 3 : 2; // the level of "Tables" and "Figures"
    std::string body;
    std::string toc = "<nav class=\"toc\" aria-label=\"Contents\">\n" + heading(2, "Contents") +
                      "<ul>\n<li><a href=\"#context\">Study context</a></li>\n";
    std::size_t inlined = 0;
    std::size_t svg_counter = 0;
    for (const auto& budget : content.budgets) {
        const Anchors anchors = anchors_of(budget, several);
        std::string tables;
        for (const auto& t : budget.tables)
            tables += render_html_table(t, anchors.prefix + "t-" + html_anchor(t.id), base + 1);
        if (budget.tables.empty())
            tables = note("This budget has no table.");
        std::vector<std::size_t> kinds;
        const std::string figures = figures_html(budget, anchors, base + 1, content.max_inline_svg_bytes,
                                                 inlined, svg_counter, kinds);
        std::string section = "<section id=\"" + anchors.tables + "\">\n" + heading(base, "Tables") + tables +
                              "</section>\n<section id=\"" + anchors.figures + "\">\n" +
                              heading(base, "Figures") + figures + "</section>\n";
        const std::string toc_inner = "<li><a href=\"#" + anchors.tables + "\">Tables</a>\n" +
                                      toc_tables(budget, anchors) + "</li>\n<li><a href=\"#" +
                                      anchors.figures + "\">Figures</a>\n" + toc_figures(kinds, anchors) +
                                      "</li>\n";
        if (several) {
            const std::string where =
                budget.folder.empty() ? std::string() : " (files in " + budget.folder + "/)";
            body +=
                "<section class=\"budget\" id=\"" + anchors.section + "\">\n" +
                heading(2, "Budget " + budget_name(budget) + where) +
                "<p class=\"caption\">Each budget is its own experiment: its tables and figures compare the "
                "algorithms under this budget only.</p>\n" +
                section + "</section>\n";
            toc += "<li><a href=\"#" + anchors.section + "\">Budget " + html_escape(budget_name(budget)) +
                   "</a>\n<ul>\n" + toc_inner + "</ul>\n</li>\n";
        } else {
            body += section;
            toc += toc_inner;
        }
    }
    toc += "</ul>\n</nav>\n";

    std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
                       // The page fetches nothing, whatever a figure or a table might hold: styles and the
                       // script are inline, and nothing else is allowed.
                       "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src "
                       "'unsafe-inline'; "
                       "script-src 'unsafe-inline'\">\n"
                       "<meta name=\"generator\" content=\"mhbench report\">\n"
                       "<title>mhbench report: " +
                       html_escape(content.study) + "</title>\n<style>" + html_report_style() +
                       "</style>\n</head>\n<body>\n";
    page += "<header>\n<h1>mhbench report: " + html_escape(content.study) + "</h1>\n";
    if (several)
        page += "<p class=\"caption\">" + std::to_string(content.budgets.size()) +
                " budgets, each reported in its own section.</p>\n";
    page += "</header>\n" + toc + "<main>\n" + context_section(content) + body + "</main>\n";
    page +=
        "<footer><p class=\"caption\">Written by <code>mhbench report</code> from the study directory alone; "
        "the tables are also in Markdown, LaTeX and CSV beside this page. Click a column header to sort "
        "(again: descending; a third time: the original order).</p></footer>\n";
    page += "<script>" + std::string(html_report_script()) + "</script>\n</body>\n</html>\n";
    return page;
}

fs::path write_html_report(const fs::path& dir, const HtmlReportContent& content) {
    const fs::path path = dir / "index.html";
    write_file_atomically(path, render_html_report(content));
    return path;
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
