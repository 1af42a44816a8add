// The "comparison" table: problems as rows and algorithms as columns, the median (IQR) of the final
// values with the marker against the reference, the best median in bold, which test made each
// problem's markers, and a w/t/l row of the markers.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "results/analysis/statistics.hpp"
#include "results/tables/comparison_common.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb::tables {

namespace {

// What the caption and the w/t/l row say of the rows as a whole, gathered while they are made.
struct ComparisonRowsSeen {
    std::size_t least_runs = SIZE_MAX;
    std::size_t most_runs = 0;
    bool any_paired = false;
    bool any_unpaired = false;
    std::vector<std::vector<std::string>> markers; // each algorithm's over the problems
};

// The lowest median of the final values on a problem over the algorithms (inf when none has runs).
double best_median(const StudyIndex& index, const std::string& problem) {
    double best = INFINITY;
    for (const auto& a : index.algorithms())
        if (const auto* g = index.find(problem, a))
            best = std::min(best, summarize(g->final_values()).median);
    return best;
}

// A pair without a successful run: blank when it has no runs at all, else says every run failed.
TableCell no_runs_cell(const RunGroup* failed) {
    if (failed == nullptr)
        return empty_cell();
    return latex_text_cell(no_successful_run_text(*failed),
                           "all " + std::to_string(failed->failed) + " failed");
}

// The markers come from rank tests of the final values, so the cell shows what they test: the
// median and the IQR (a mean can sit on the other side of the reference's than most runs).
TableCell median_cell(const RunGroup& g, const std::string& marker, double best) {
    const Summary s = summarize(g.final_values());
    TableCell cell = spread_cell(s.median, s.iqr(), marker, {3, -1}, {2, -1});
    // No bold when the best median is infinite: nothing is best where every median is inf.
    cell.bold = std::isfinite(best) && s.median == best;
    return cell;
}

std::vector<TableCell> problem_row(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                                   const std::string& p, ComparisonRowsSeen& seen) {
    std::vector<TableCell> row = {text_cell(p)};
    const double best = best_median(index, p);
    for (std::size_t j = 0; j < index.algorithms().size(); ++j) {
        const std::string& a = index.algorithms()[j];
        const auto* g = index.find(p, a);
        if (g == nullptr) {
            row.push_back(no_runs_cell(index.group(p, a)));
            continue;
        }
        seen.least_runs = std::min(seen.least_runs, g->runs.size());
        seen.most_runs = std::max(seen.most_runs, g->runs.size());
        std::string marker;
        for (const auto& c : comparisons)
            if (c.problem == p && c.algorithm == a) {
                marker = c.marker;
                seen.markers[j].push_back(c.marker);
            }
        row.push_back(median_cell(*g, marker, best));
    }
    const bool compared = std::any_of(comparisons.begin(), comparisons.end(),
                                      [&](const Comparison& c) { return c.problem == p; });
    const bool paired = index.paired(p);
    seen.any_paired = seen.any_paired || (compared && paired);
    seen.any_unpaired = seen.any_unpaired || (compared && !paired);
    row.push_back(text_cell(!compared ? "" : (paired ? "signed-rank (paired)" : "rank-sum")));
    return row;
}

// Under the rule, each algorithm's wins, ties and losses in its own column.
std::vector<TableCell> win_tie_loss_footer(const StudyIndex& index, const ComparisonRowsSeen& seen,
                                           std::size_t width, const std::string& reference) {
    std::vector<TableCell> row(width, empty_cell());
    row[0] = text_cell("w/t/l");
    for (std::size_t j = 0; j < seen.markers.size(); ++j)
        if (index.algorithms()[j] != reference)
            row[j + 1] = text_cell(win_tie_loss(seen.markers[j]));
    return row;
}

const MarkerTestsWording comparison_tests_wording = {
    .paired = "two-sided Wilcoxon signed-rank test of the paired differences (runs paired by seed: common "
              "random numbers)",
    .paired_where = " on the problems marked so, ",
    .unpaired = "two-sided Wilcoxon rank-sum test (Mann-Whitney U)",
    .unpaired_where = " on the others (seeds differ)",
    .none = "none (no problem has runs of the reference and another algorithm)"};

std::string runs_range(const ComparisonRowsSeen& seen) {
    return seen.least_runs == seen.most_runs || seen.least_runs == SIZE_MAX
               ? std::to_string(seen.most_runs)
               : std::to_string(seen.least_runs) + "-" + std::to_string(seen.most_runs);
}

// What the markers are, for methods.tex and the Markdown caption.
std::string markers_paragraph(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                              const ComparisonOptions& options, const ComparisonRowsSeen& seen) {
    return "Markers against the reference " + index.label(options.reference) + ": " +
           marker_tests_text(seen.any_paired, seen.any_unpaired, comparison_tests_wording) +
           " of the final values, Holm correction across each problem's comparisons, alpha = " +
           alpha_text(options.alpha) + "; + better, - worse, = no significant difference." +
           degenerate_tests_note(comparisons) + (comparisons.empty() ? "" : wtl_note);
}

std::string comparison_caption(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                               const ComparisonOptions& options, const ComparisonRowsSeen& seen) {
    return "Median (IQR = q75 - q25) of the final best-so-far value over " + runs_range(seen) +
           " runs; lowest median in bold. The median is shown because the markers come from rank tests "
           "of the final values, which compare where the runs lie, not their mean. " +
           markers_paragraph(index, comparisons, options, seen) + left_out_notes(index);
}

// LaTeX: the IQR under the median keeps the columns narrow; the test is said once when it is the
// same for every problem.
void comparison_latex_layout(Table& t) {
    t.latex_spread_below = true;
    t.latex_column(0).fold_constant = true;
    t.latex_column(0).wrap = true; // specs break after ',' and ':'; more algorithms fit beside them
    t.latex_column(t.header.size() - 1).fold_constant = true;
}

} // namespace

Table comparison_table(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                       const ComparisonOptions& options) {
    Table t;
    t.id = "comparison";
    t.title = "Final values: median (IQR) per problem and algorithm";
    t.header = {"Problem"};
    for (const auto& a : index.algorithms())
        t.header.push_back(a == options.reference ? index.label(a) + " (reference)" : index.label(a));
    t.header.push_back("Markers by");
    ComparisonRowsSeen seen;
    seen.markers.resize(index.algorithms().size());
    for (const auto& p : index.problems())
        t.add_row(problem_row(index, comparisons, p, seen));
    if (!comparisons.empty())
        t.add_footer(win_tie_loss_footer(index, seen, t.header.size(), options.reference));
    t.caption = comparison_caption(index, comparisons, options, seen);
    t.latex_note = "Median (IQR) of the final value over " + runs_range(seen) +
                   " runs; lowest in bold. +, =, -: better than, not different from, worse than " +
                   index.label(options.reference) + " (Methods)." + left_out_notes(index);
    t.methods = {markers_paragraph(index, comparisons, options, seen)};
    comparison_latex_layout(t);
    format_columns(t);
    return t;
}

} // namespace mhb::tables
