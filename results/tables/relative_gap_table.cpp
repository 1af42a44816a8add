#include "results/tables/relative_gap_table.hpp"

#include <algorithm>
#include <cmath>

#include "results/analysis/budget_target.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb {

namespace {

// "20", or "18-20" when the pairs ran different numbers of runs.
std::string runs_range(const RelativeGaps& gaps) {
    std::size_t least = SIZE_MAX;
    std::size_t most = 0;
    for (const auto& row : gaps.cells)
        for (const auto& c : row) {
            least = std::min(least, c.runs + c.failed);
            most = std::max(most, c.runs + c.failed);
        }
    return least == most || least == SIZE_MAX ? std::to_string(most)
                                              : std::to_string(least) + "-" + std::to_string(most);
}

std::string caption_of(const StudyIndex& index, const RelativeGaps& gaps,
                       const std::vector<std::string>& names) {
    const auto target = budget_target(index.budget());
    std::vector<std::string> optima;
    for (std::size_t p = 0; p < gaps.problems.size(); ++p)
        optima.push_back(names[p] + " (" + gaps.problems[p] + "): f* = " + format_number(gaps.f_opt[p], 8));
    std::string caption =
        "Relative gap (f - f*) / |f*| of each run's final best value, its median over the " +
        runs_range(gaps) +
        " runs of each algorithm on each problem (R's type 7; lowest median of each problem in bold); a gap "
        "of 0 or below is f* reached to the precision of doubles, or a best-known f* bettered. Success "
        "rate: runs that reached the study's target, " +
        (target ? target->condition() : std::string("none set")) +
        ", over all runs (a failed run counts as unsuccessful); a run stops at the target, so a median just "
        "under it says that most runs reached it, not how far below they would have gone. f* per problem: " +
        join(optima, "; ") + ".";
    if (!gaps.left_out.empty())
        caption += " Left out, having no known, non-zero f*: " + join(gaps.left_out, ", ") + ".";
    return caption + left_out_notes(index);
}

} // namespace

Table relative_gap_table(const StudyIndex& index, const RelativeGaps& gaps) {
    const std::vector<std::string>& names = gaps.names;
    Table t;
    t.id = "relative_gaps";
    t.title = "Median relative gap to f* and success rate per problem";
    t.header = {"Algorithm"};
    for (const auto& name : names) {
        t.header.push_back(name + ": median gap");
        t.header.push_back(name + ": success");
    }
    std::vector<double> best(gaps.problems.size(), INFINITY);
    for (const auto& row : gaps.cells)
        for (std::size_t p = 0; p < row.size(); ++p)
            if (!std::isnan(row[p].median))
                best[p] = std::min(best[p], row[p].median);
    for (std::size_t a = 0; a < gaps.algorithms.size(); ++a) {
        std::vector<TableCell> row = {text_cell(index.label(gaps.algorithms[a]))};
        for (std::size_t p = 0; p < gaps.problems.size(); ++p) {
            const RelativeGapCell& c = gaps.cells[a][p];
            TableCell median =
                !std::isnan(c.median) ? number_cell(c.median, 3)
                : c.failed > 0
                    ? tables::latex_text_cell("no successful run (" + std::to_string(c.failed) + " failed)",
                                              "all " + std::to_string(c.failed) + " failed")
                    : tables::empty_cell();
            median.bold = std::isfinite(best[p]) && c.median == best[p];
            row.push_back(std::move(median));
            const double rate = c.success_rate();
            row.push_back(std::isnan(rate) ? tables::empty_cell() : fixed_cell(rate, 2));
        }
        t.add_row(std::move(row));
    }
    t.caption = caption_of(index, gaps, names);
    t.latex_column(0).key = true;
    for (std::size_t p = 0; p < names.size(); ++p) // a problem's two columns stay together
        for (std::size_t k = 0; k < 2; ++k)
            t.latex_column(1 + 2 * p + k).group = names[p];
    format_columns(t);
    return t;
}

} // namespace mhb
