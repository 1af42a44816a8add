// A report table as data (header, rows of cells, a caption) and its three renderings: Markdown
// (for the console and READMEs), LaTeX (booktabs; compiles with a plain `article` plus
// `booktabs`) and CSV (full-precision values, for other tools).
#pragma once

#include <string>
#include <vector>

namespace mhb {

struct TableCell {
    std::string text;  // as shown in Markdown and LaTeX
    std::string value; // as written to CSV (full precision); empty means "same as text"
    bool bold = false; // the best value of its row or column, say
};

struct Table {
    std::string id;      // file stem in the report directory, e.g. "table2_fitness"
    std::string title;   // one line: the Markdown heading and the start of the LaTeX caption
    std::string caption; // what the reader must know: tests, alpha, correction, runs, sources
    std::vector<std::string> header;
    std::vector<std::vector<TableCell>> rows; // each row has header.size() cells

    void add_row(std::vector<TableCell> row);
};

std::string render_markdown(const Table& table);
std::string render_latex(const Table& table);
std::string render_csv(const Table& table);

// Escapes the characters LaTeX treats specially in text mode.
std::string latex_escape(const std::string& text);

// What a cell shows for an undefined value (a NaN, e.g. the mean of +inf and -inf), since no table
// prints "nan": an em dash in Markdown, "---" in LaTeX, an empty field in CSV.
inline constexpr const char* undefined_text = "\u2014";

// Number formatting shared by the report: `significant` significant digits ("%.*g"), "inf" and
// "-inf" spelled out, undefined_text for NaN; and full precision for CSV.
std::string format_number(double value, int significant = 5);
std::string format_fixed(double value, int decimals);
TableCell number_cell(double value, int significant = 5);
TableCell text_cell(std::string text);

} // namespace mhb
