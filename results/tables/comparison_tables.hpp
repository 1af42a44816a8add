// The statistics tables of a study (issue 5), for any problems:
//  - "summary": per problem x algorithm the descriptive statistics, evaluations spent, error to the
//    known optimum, success rate and ERT (COCO) to the study's target, median values at fixed
//    fractions of one evaluation count per problem (the study's evaluation budget, else the most
//    any run on the problem spent), the same counts for every algorithm;
//  - "tests": per problem each algorithm against the reference: Wilcoxon rank-sum p, Holm-adjusted
//    across that problem's comparisons, Vargha-Delaney A12; where the problem's runs are paired by
//    seed (StudyIndex::paired), also the Wilcoxon signed-rank test of the paired differences (Holm
//    likewise); the +/=/- marker from the signed-rank test when paired, the rank-sum test otherwise;
//    a w/t/l row per algorithm counts its markers;
//  - "comparison": the generic layout, problems as rows and algorithms (labels) as columns, median
//    (IQR) and marker (the markers come from rank tests: the median is what they are about), best
//    median in bold, which test made each problem's markers, and a w/t/l row of the markers;
//  - "across_problems" (two or more problems): Friedman average ranks with the Holm post-hoc against
//    the reference, and Wilcoxon signed-rank on per-problem medians (paired by problem).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "results/analysis/hypothesis_tests.hpp"
#include "results/analysis/problem_medians.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

struct ComparisonOptions {
    std::string reference; // an algorithm spec of the study
    double alpha = 0.05;
    std::vector<double> budget_fractions = {0.01, 0.1, 1.0};
};

// The algorithm spec `requested` names: a spec of the study, a label, or a name (before ':') that
// exactly one of its algorithms has. Without a request: `itlbo` (all defaults) if the study has it,
// else the first ITLBO variant, else the first algorithm.
// Throws std::invalid_argument listing the study's algorithms when it names none or several.
std::string resolve_reference(const StudyIndex& index, const std::optional<std::string>& requested);

// "+" when `algorithm` is significantly better (lower) than the reference at `alpha` after
// adjustment, "-" when significantly worse, "=" otherwise. a12 is A12(algorithm, reference).
std::string comparison_marker(double adjusted_p, double a12, double alpha);
// The same from the signed-rank test of the paired differences algorithm - reference: "+" when
// significant and V lies below its null mean n (n + 1) / 4 (n = non-zero differences), i.e. the
// algorithm's values tend lower; "-" above; "=" otherwise.
std::string signed_rank_marker(double adjusted_p, const TestResult& signed_rank, std::size_t nonzero_pairs,
                               double alpha);
// "+", "=" and "-" counted: "w/t/l", the wins, ties and losses of one algorithm against the reference.
std::string win_tie_loss(const std::vector<std::string>& markers);
// A +/=/- marker as a cell: text in Markdown and CSV, maths in LaTeX.
TableCell marker_cell(const std::string& marker);

std::vector<Table> comparison_tables(const StudyIndex& index, const ComparisonOptions& options);

} // namespace mhb
