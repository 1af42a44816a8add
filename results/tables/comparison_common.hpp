// What the tables of comparison_tables() share: each algorithm's tests against the reference on each
// problem, the cells and caption phrases about those tests, and the builders of the four tables
// (summary_table.cpp, tests_table.cpp, comparison_table.cpp, across_problems_table.cpp), which
// comparison_tables() puts together. Internal to results/tables/.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "results/analysis/hypothesis_tests.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills
#include "results/tables/comparison_tables.hpp"

namespace mhb::tables {

// One algorithm against the reference on one problem.
struct Comparison {
    std::string problem;
    std::string algorithm;
    TestResult test; // rank-sum, always
    double adjusted_p = 1.0;
    double a12 = 0.5;
    bool paired = false; // the problem's runs are paired by seed: the signed-rank test decides
    std::size_t pairs = 0;
    TestResult paired_test; // signed-rank on the paired differences (algorithm - reference)
    double paired_adjusted_p = 1.0;
    std::string marker;
    // Degenerate tests, which the tables report by convention (z = 0, p = 1, '=') where R's
    // wilcox.test gives NaN: every value of both samples equal; every paired difference zero.
    bool every_value_tied = false;
    bool every_difference_zero = false;
};

// Every algorithm but the reference against it, on each problem where the reference has successful
// runs, in the index's order; p-values Holm-adjusted across each problem's comparisons.
std::vector<Comparison> compare_with_reference(const StudyIndex& index, const ComparisonOptions& options);

// alpha as the captions print it.
std::string alpha_text(double alpha);
// A test's name as a cell; LaTeX says only its variant (the caption names the test): "exact" or
// "normal approx." (with tie and continuity correction).
TableCell test_cell(const TestResult& test);
// What a caption naming the tests must add when some were degenerate (empty when none was).
std::string degenerate_tests_note(const std::vector<Comparison>& comparisons);
// What a caption says of the w/t/l rows under the rule.
inline constexpr const char* wtl_note =
    " Rows under the rule: w/t/l, the number of problems on which the algorithm is significantly better "
    "than the reference (+), not significantly different (=) and significantly worse (-).";

// The tables, as comparison_tables.hpp describes them.
Table summary_table(const StudyIndex& index, const ComparisonOptions& options);
Table tests_table(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                  const ComparisonOptions& options);
Table comparison_table(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                       const ComparisonOptions& options);
// None with fewer than two problems on which every algorithm has runs, or fewer than two algorithms.
std::optional<Table> across_problems_table(const StudyIndex& index, const ComparisonOptions& options);

} // namespace mhb::tables
