#include "results/latex/latex_document.hpp"

#include <string>
#include <vector>

#include "results/latex/latex_table.hpp"
#include "results/latex/latex_text.hpp"
#include "results/store/context_ini.hpp" // the report shows where the study was run

namespace mhb {

namespace {

// A path or a command line: escaped, with a line break allowed after '/', ',' and ':' (a path has
// no space to break at).
std::string breakable(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        out += latex_escape(std::string(1, text[i]));
        if ((text[i] == '/' || text[i] == ',' || text[i] == ':' || text[i] == '=') && i + 1 < text.size() &&
            text[i + 1] != ' ')
            out += "\\allowbreak{}";
    }
    return out;
}

// context.ini as a two-column table of key and value (values wrap). Of the history of a resumed
// study ("session" lines, first first), the first and the latest session are shown.
std::string context_table(const std::string& context, std::string& date) {
    std::string rows;
    std::vector<std::string> sessions;
    for (const auto& [key, value] : context_entries(context)) {
        if (key == "date_utc")
            date = value;
        if (key == "session")
            sessions.push_back(value);
        else
            rows += breakable(key) + " & " + breakable(value) + " \\\\\n";
    }
    if (!sessions.empty())
        rows += "first session & " + breakable(sessions.front()) + " \\\\\n";
    if (sessions.size() > 1)
        rows += "latest session (of " + std::to_string(sessions.size()) + ") & " +
                breakable(sessions.back()) + " \\\\\n";
    if (rows.empty())
        return "";
    return "\\section*{Study context}\n{\\footnotesize\n"
           "\\begin{tabular}{@{}l>{\\raggedright\\arraybackslash}p{250pt}@{}}\n" +
           rows + "\\end{tabular}\\par}\n";
}

} // namespace

std::string latex_document(const std::string& study_directory, const std::string& context,
                           const std::vector<LatexSection>& sections) {
    std::string date;
    const std::string context_part = context_table(context, date);
    std::string out =
        "% All tables of the report (written by mhbench report). Compiles with pdflatex and TeX Live's\n"
        "% latex-base and latex-recommended packages; each table also stands alone in <id>.tex.\n"
        "\\documentclass{article}\n"
        "\\usepackage[T1]{fontenc}\n"
        "\\usepackage{lmodern}\n"
        "\\usepackage{booktabs}\n"
        "\\usepackage{array}\n"
        "\\usepackage{graphicx}\n"
        "% Tables follow one another with no text between: let a page hold several, and float pages\n"
        "% fill up, so that they are placed near where they are listed. A table taller than a page is\n"
        "% several floats, which keep their order like any others.\n"
        "\\setcounter{topnumber}{4}\n\\setcounter{bottomnumber}{4}\n\\setcounter{totalnumber}{8}\n"
        "\\renewcommand{\\topfraction}{0.95}\n\\renewcommand{\\bottomfraction}{0.95}\n"
        "\\renewcommand{\\textfraction}{0.05}\n\\renewcommand{\\floatpagefraction}{0.6}\n"
        "\\title{mhbench report:\\\\ \\texttt{" +
        breakable(study_directory) + "}}\n\\author{}\n\\date{" + breakable(date) + "}\n" +
        "\\begin{document}\n\\maketitle\n" + context_part;
    for (const auto& section : sections) {
        if (!section.heading.empty())
            out += "\\clearpage\n\\section{" + latex_escape(section.heading) + "}\n";
        // Every table is floats (a tall one several, its rows continued under the same number), so
        // none overtakes another still waiting for a place, and no \clearpage is needed between them.
        if (const std::string methods = latex_methods(section.tables); !methods.empty())
            out += "\n\\subsection*{Methods}\n" + methods;
        for (const auto& t : section.tables)
            out.append("\n").append(render_latex(t));
    }
    return out + "\n\\end{document}\n";
}

} // namespace mhb
