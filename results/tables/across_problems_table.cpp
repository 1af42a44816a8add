// The "across_problems" table (two or more problems): Friedman average ranks of the per-problem
// medians with the Holm post-hoc against the reference, and the Wilcoxon signed-rank test of each
// algorithm's medians against the reference's, paired by problem.
#include <algorithm>
#include <cmath>

#include "results/analysis/problem_medians.hpp"
#include "results/tables/comparison_common.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb::tables {

namespace {

// Each algorithm but the reference (the control) against it, Holm-adjusted across the algorithms;
// the adjusted p-values are in the order of the algorithms with the control left out.
struct AgainstControl {
    std::vector<double> posthoc_adjusted;
    std::vector<TestResult> signed_tests; // by algorithm; the control's is empty
    std::vector<double> signed_adjusted;
};

AgainstControl against_control(const std::vector<std::vector<double>>& medians,
                               const FriedmanResult& friedman, std::size_t problems, std::size_t control) {
    const std::size_t algorithms = friedman.average_ranks.size();
    const std::vector<double> posthoc = friedman_posthoc_p_values(friedman.average_ranks, problems, control);
    AgainstControl out;
    out.signed_tests.resize(algorithms);
    std::vector<double> posthoc_raw;
    std::vector<double> signed_raw;
    for (std::size_t j = 0; j < algorithms; ++j) {
        if (j == control)
            continue;
        std::vector<double> x;
        std::vector<double> y;
        for (const auto& row : medians) {
            x.push_back(row[j]);
            y.push_back(row[control]);
        }
        out.signed_tests[j] = signed_rank_test(x, y);
        posthoc_raw.push_back(posthoc[j]);
        signed_raw.push_back(out.signed_tests[j].p_value);
    }
    out.posthoc_adjusted = holm_adjust(posthoc_raw);
    out.signed_adjusted = holm_adjust(signed_raw);
    return out;
}

void add_ranking_rows(Table& t, const StudyIndex& index, const FriedmanResult& friedman,
                      const AgainstControl& tests, std::size_t control) {
    const auto& algorithms = index.algorithms();
    double best_rank = INFINITY;
    for (double r : friedman.average_ranks)
        best_rank = std::min(best_rank, r);
    std::size_t i = 0; // into the adjusted p-values, which leave the control out
    for (std::size_t j = 0; j < algorithms.size(); ++j) {
        TableCell rank = number_cell(friedman.average_ranks[j], 4);
        rank.bold = friedman.average_ranks[j] == best_rank;
        if (j == control) {
            t.add_row({text_cell(index.label(algorithms[j]) + " (reference)"), rank, empty_cell(),
                       empty_cell(), empty_cell(), empty_cell(), empty_cell()});
            continue;
        }
        const TestResult& signed_test = tests.signed_tests[j];
        t.add_row({text_cell(index.label(algorithms[j])), rank, number_cell(tests.posthoc_adjusted[i], 3),
                   number_cell(signed_test.statistic, 6), number_cell(signed_test.p_value, 3),
                   number_cell(tests.signed_adjusted[i], 3), test_cell(signed_test)});
        ++i;
    }
}

std::string across_problems_caption(const StudyIndex& index, const ComparisonOptions& options,
                                    const FriedmanResult& friedman, std::size_t problems) {
    const std::size_t left_out = index.problems().size() - problems;
    return "Over " + std::to_string(problems) +
           " problems (per-problem medians of the final values; rank 1 = "
           "lowest" +
           (left_out == 0 ? std::string()
                          : "; " + std::to_string(left_out) + (left_out == 1 ? " problem" : " problems") +
                                " left out, on which some algorithm has no successful run") +
           "). Friedman test: chi-square = " + format_number(friedman.chi_square, 5) +
           ", df = " + format_number(friedman.degrees_of_freedom) +
           ", p = " + format_number(friedman.p_value, 3) +
           ". Post-hoc: z = (R_j - R_ref) / sqrt(k(k+1)/(6N)) against the reference, Holm-adjusted. Wilcoxon "
           "signed-rank test of each algorithm's per-problem medians against the reference's, paired by "
           "problem, Holm-adjusted; alpha = " +
           alpha_text(options.alpha) + "." + left_out_notes(index);
}

void across_problems_latex_layout(Table& t) {
    set_latex_headers(t, {{2, "Post-hoc $p$\\\\(Holm)"},
                          {3, "Signed-\\\\rank $V$"},
                          {4, "Signed-\\\\rank $p$"},
                          {5, "Signed-\\\\rank $p$\\\\(Holm)"},
                          {6, "Signed-rank\\\\test"}});
    t.latex_column(6).fold_constant = true;
}

} // namespace

std::optional<Table> across_problems_table(const StudyIndex& index, const ComparisonOptions& options) {
    const auto medians_or_none = per_problem_medians(index);
    if (!medians_or_none)
        return std::nullopt;
    const auto& [problems, medians] = *medians_or_none;
    const auto& algorithms = index.algorithms();
    const FriedmanResult friedman = friedman_test(medians);
    const auto control = static_cast<std::size_t>(
        std::find(algorithms.begin(), algorithms.end(), options.reference) - algorithms.begin());
    Table t;
    t.id = "across_problems";
    t.title = "Across problems: Friedman average ranks and Wilcoxon signed-rank against " +
              index.label(options.reference);
    t.header = {"Algorithm",     "Average rank",         "Post-hoc p (Holm)", "Signed-rank V",
                "Signed-rank p", "Signed-rank p (Holm)", "Signed-rank test"};
    add_ranking_rows(t, index, friedman, against_control(medians, friedman, problems.size(), control),
                     control);
    across_problems_latex_layout(t);
    t.caption = across_problems_caption(index, options, friedman, problems.size());
    format_columns(t);
    return t;
}

} // namespace mhb::tables
