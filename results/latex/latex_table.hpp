// render_latex: a table (results/table_model/table.hpp) laid out for a journal's one-column text width.
//
// Every table must fit the 345 pt text width of a one-column `article` (default geometry), in
// \footnotesize with \tabcolsep = 4 pt (3 pt when that is what keeps it whole). The layout is decided
// before TeX runs (a file for each step: results/latex/latex_layout.hpp), from estimated widths
// (results/latex/latex_text.hpp, latex_numbers.hpp: within a point or two of what pdflatex
// measures; only 96 % of the width is used):
//  1. a column whose every row holds the same value (LatexColumn::fold_constant: the problem of a
//     one-problem study, the name of a test, f*) is said once in the notes, a column without any
//     value is left out (the notes name it), and a LatexColumn::heading column (the problem of
//     the summary's rows) becomes a line above each run of rows with its value;
//  2. long text wraps in a ragged-right paragraph column (specs break after ',' and ':');
//  3. a table still too wide is split into several tables that repeat the key columns, whole
//     column groups first (LatexColumn::group: the summary's location and spread, range, target
//     and budget columns, the tests' rank-sum and signed-rank parts); captions name the parts;
//  4. only a single column too wide for the page on its own gets \resizebox.
// A part up to 252 pt wide (one column of a two-column IEEE paper) is a `table`; a wider one is a
// `table*`, which spans both columns of a two-column class and is a plain table in one column.
// A part taller than a page is split by rows into consecutive floats of the same environment, each
// with the column header: the first has the caption, the label and the notes; the others the
// same table number (\addtocounter{table}{-1}) and the caption with "(continued)". The height is
// estimated like the width, from heights pdflatex measured, and each float must fit 96 % of the
// smallest text height of the targets: 550 pt, a one-column article's (IEEEtran conference 672 pt,
// elsarticle 5p 682 pt). The floats are as few as fit, as evenly filled as the breaks allow; they
// break between runs of rows under one heading where that leaves a float at least half full
// (else inside a run, at least two of its rows above the break), a float's first row is
// headed (the heading repeats when a run continues), a heading never ends a float, and the w/t/l
// rows go with the last. Floats, unlike a longtable, work in one- and two-column documents alike.
// Numbers are maths padded to their column's widest tail (results/latex/latex_numbers.hpp), so plain `r`
// columns line every decimal point up: siunitx is in Debian's texlive-science, which a reader (and
// CI) may lack, and its S columns could not take our composite cells (median, IQR, marker).
// The caption is the title alone (no "Table N:" of the Markdown title: LaTeX numbers the tables);
// the notes under it are the table's short note (Table::latex_note, a few lines; the Markdown
// caption where it has none) after the columns said once. The method text the tables share
// (Table::methods: the tests, the markers, Holm, alpha) is said once for all in methods.tex
// (latex_methods), which a paper \input's in its text.
#pragma once

#include <string>
#include <vector>

#include "results/table_model/table.hpp" // a renderer sees tables, never runs

namespace mhb {

std::string render_latex(const Table& table);

// methods.tex: each distinct Table::methods text of `tables` once, in their order, as paragraphs of
// the paper's text (no float); "" when no table has one.
std::string latex_methods(const std::vector<Table>& tables);

} // namespace mhb
