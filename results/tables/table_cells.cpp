// The shared cells and caption phrases of table_cells.hpp that are more than a line.
#include "results/tables/table_cells.hpp"

#include "results/tables/comparison_tables.hpp"

namespace mhb::tables {

void set_latex_headers(Table& t, std::initializer_list<std::pair<std::size_t, const char*>> headers) {
    for (const auto& [column, header] : headers)
        t.latex_column(column).header = header;
}

std::vector<double> run_evaluations(const RunGroup& g) {
    std::vector<double> evaluations;
    for (const auto* r : g.runs)
        evaluations.push_back(static_cast<double>(r->evaluations));
    return evaluations;
}

std::vector<double> run_errors(const RunGroup& g) {
    std::vector<double> errors;
    for (const auto* r : g.runs)
        if (r->error())
            errors.push_back(*r->error());
    return errors;
}

std::vector<TableCell> win_tie_loss_row(std::size_t width, const std::string& algorithm_label,
                                        std::size_t result_column, const std::vector<std::string>& markers) {
    std::vector<TableCell> row(width, empty_cell());
    row[0] = text_cell("w/t/l");
    row[1] = text_cell(algorithm_label);
    row[result_column] = text_cell(win_tie_loss(markers));
    return row;
}

std::string marker_tests_text(bool any_paired, bool any_unpaired, const MarkerTestsWording& wording) {
    std::string tests;
    if (any_paired)
        tests = wording.paired;
    if (any_paired && any_unpaired)
        tests += wording.paired_where;
    if (any_unpaired)
        tests += wording.unpaired;
    if (any_paired && any_unpaired)
        tests += wording.unpaired_where;
    if (tests.empty())
        tests = wording.none;
    return tests;
}

} // namespace mhb::tables
