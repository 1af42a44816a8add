// Cells and caption phrases that several tables of the report share (summary, tests, comparison,
// the paper's and the CEC tables), so that each says them the same way. Internal to results/tables/.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb::tables {

// A cell with nothing to show: no value, or one that does not apply to the row.
inline TableCell empty_cell() {
    return text_cell("");
}

// A cell whose LaTeX says `text` otherwise (a symbol, a shorter form for a narrow column).
inline TableCell latex_text_cell(std::string text, std::string latex) {
    TableCell cell = text_cell(std::move(text));
    cell.latex = std::move(latex);
    return cell;
}

// "successful/total" runs of a group: a failed run counts in the total only.
inline std::string runs_text(const RunGroup& g) {
    return std::to_string(g.runs.size()) + "/" + std::to_string(g.runs.size() + g.failed);
}

// What a group without a successful run shows where its statistics would be.
inline std::string no_successful_run_text(const RunGroup& g) {
    return "no successful run (" + std::to_string(g.failed) + " failed)";
}

// LaTeX headers where the text's are too wide or want maths: {column, header} pairs.
void set_latex_headers(Table& t, std::initializer_list<std::pair<std::size_t, const char*>> headers);

// The evaluations each successful run of a group spent, and the errors f - f* of those that know f*.
std::vector<double> run_evaluations(const RunGroup& g);
std::vector<double> run_errors(const RunGroup& g);

// A footer row "w/t/l | <algorithm> | ... | <wins/ties/losses of its markers>", blank elsewhere.
std::vector<TableCell> win_tie_loss_row(std::size_t width, const std::string& algorithm_label,
                                        std::size_t result_column, const std::vector<std::string>& markers);

// How a caption names the tests that made its markers: `paired` where runs pair by seed, `unpaired`
// where they do not; when a table has both, each is followed by where it applies.
struct MarkerTestsWording {
    const char* paired;
    const char* paired_where; // after `paired` when some rows are unpaired
    const char* unpaired;
    const char* unpaired_where; // after `unpaired` when some rows are paired
    const char* none;           // when no row was tested
};
std::string marker_tests_text(bool any_paired, bool any_unpaired, const MarkerTestsWording& wording);

} // namespace mhb::tables
