// report.tex: every table of a report in one LaTeX document that pdflatex compiles with TeX Live's
// latex-base and latex-recommended packages alone (T1 fonts, Latin Modern, booktabs, array,
// graphicx): a title naming the study directory, the study's context, and a section per
// budget when there are several. Each table also stands alone in its <id>.tex
// (results/table_model/table.hpp).
#pragma once

#include <string>
#include <vector>

#include "results/table_model/table.hpp" // a renderer sees tables, never runs

namespace mhb {

struct LatexSection {
    std::string heading; // "Budget iterations=150"; empty: the tables without a section
    std::vector<Table> tables;
};

// `context` is the study's context.ini (key = value lines; comments are left out).
std::string latex_document(const std::string& study_directory, const std::string& context,
                           const std::vector<LatexSection>& sections);

} // namespace mhb
