// The "tests" table: per problem each algorithm against the reference, by the rank-sum test and,
// where the runs pair by seed, the signed-rank test of the paired differences, with the marker each
// comparison gets and a w/t/l row per algorithm.
#include "results/tables/comparison_common.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb::tables {

namespace {

const std::vector<std::string> test_columns = {"Problem",
                                               "Algorithm",
                                               "Rank-sum test",
                                               "W",
                                               "z",
                                               "p",
                                               "p (Holm)",
                                               "A12",
                                               "Paired runs",
                                               "Signed-rank test",
                                               "V",
                                               "Signed-rank z",
                                               "Signed-rank p",
                                               "Signed-rank p (Holm)",
                                               "Result",
                                               "Result by"};
constexpr std::size_t result_column = 14;

std::vector<TableCell> comparison_row(const StudyIndex& index, const Comparison& c) {
    std::vector<TableCell> row = {text_cell(c.problem),
                                  text_cell(index.label(c.algorithm)),
                                  test_cell(c.test),
                                  number_cell(c.test.statistic, 6),
                                  c.test.exact ? empty_cell() : number_cell(c.test.z, 3),
                                  number_cell(c.test.p_value, 3),
                                  number_cell(c.adjusted_p, 3),
                                  fixed_cell(c.a12, 3)}; // in [0, 1]: three decimals align
    if (c.paired) {
        row.push_back(number_cell(static_cast<double>(c.pairs), 6));
        row.push_back(test_cell(c.paired_test));
        row.push_back(number_cell(c.paired_test.statistic, 6));
        row.push_back(c.paired_test.exact ? empty_cell() : number_cell(c.paired_test.z, 3));
        row.push_back(number_cell(c.paired_test.p_value, 3));
        row.push_back(number_cell(c.paired_adjusted_p, 3));
    } else {
        row.push_back(text_cell("no (seeds differ)"));
        for (int i = 0; i < 5; ++i)
            row.push_back(empty_cell());
    }
    row.push_back(marker_cell(c.marker));
    row.push_back(text_cell(c.paired ? "signed-rank" : "rank-sum"));
    return row;
}

// Under the rule, each algorithm's wins, ties and losses over the problems.
void add_win_tie_loss_rows(Table& t, const StudyIndex& index, const std::vector<Comparison>& comparisons) {
    for (const auto& a : index.algorithms()) {
        std::vector<std::string> markers;
        for (const auto& c : comparisons)
            if (c.algorithm == a)
                markers.push_back(c.marker);
        if (!markers.empty())
            t.add_footer(win_tie_loss_row(t.header.size(), index.label(a), result_column, markers));
    }
}

// The problems with runs of the reference, every one of which failed: " Not tested (...): a, b."
std::string untested_note(const StudyIndex& index, const std::string& reference) {
    std::vector<std::string> untested;
    for (const auto& p : index.problems())
        if (index.find(p, reference) == nullptr && index.group(p, reference) != nullptr)
            untested.push_back(p);
    if (untested.empty())
        return "";
    std::string note = " Not tested (every run of the reference failed):";
    for (std::size_t i = 0; i < untested.size(); ++i)
        note += (i == 0 ? " " : ", ") + untested[i];
    return note + ".";
}

std::string tests_caption(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                          const ComparisonOptions& options) {
    bool any_paired = false;
    bool any_unpaired = false;
    for (const auto& c : comparisons) {
        any_paired = any_paired || c.paired;
        any_unpaired = any_unpaired || !c.paired;
    }
    std::string caption =
        "Two-sided Wilcoxon rank-sum test (Mann-Whitney U; W = U of the algorithm) of each algorithm's "
        "final values against the reference's, Holm-adjusted across the comparisons of each problem; A12 = "
        "Vargha-Delaney effect size P(algorithm > reference) + P(=)/2 (below 0.5: the algorithm tends to "
        "lower, better values).";
    if (any_paired)
        caption +=
            " Where the runs are paired (every algorithm's run r on the problem has the same seed: common "
            "random numbers), also the two-sided Wilcoxon signed-rank test of the paired differences "
            "algorithm - reference over the run indices both completed (V = sum of the ranks of positive "
            "differences; zero differences dropped, as R's wilcox.test(paired = TRUE)), Holm-adjusted across "
            "the comparisons of each problem.";
    caption += std::string(" Result (alpha = ") + alpha_text(options.alpha) +
               ") from the test named in \"Result by\": " +
               (any_paired && any_unpaired ? "the signed-rank test where runs are paired, the rank-sum test "
                                             "where they are not"
                                           : (any_paired ? "the signed-rank test (all runs paired)"
                                                         : "the rank-sum test (no runs paired)")) +
               ". +: significantly better than the reference, -: significantly worse, =: no significant "
               "difference. Test variants: exact = the exact null distribution, normal approx. = the normal "
               "approximation with tie and continuity correction." +
               degenerate_tests_note(comparisons) + wtl_note;
    return caption + untested_note(index, options.reference) + left_out_notes(index);
}

// LaTeX: a rank-sum part and a signed-rank part when both do not fit; the name of a test is said
// once in the notes when every row has the same.
void tests_latex_layout(Table& t) {
    t.latex_column(0).fold_constant = true;
    t.latex_column(0).heading = true;
    t.latex_column(1).key = true;
    for (std::size_t c = 2; c <= 7; ++c)
        t.latex_column(c).group = "rank-sum test";
    for (std::size_t c = 8; c <= 13; ++c)
        t.latex_column(c).group = "signed-rank test";
    t.latex_column(result_column).group = "result";
    t.latex_column(result_column + 1).group = "result";
    for (const std::size_t c : {std::size_t{2}, std::size_t{9}, result_column + 1})
        t.latex_column(c).fold_constant = true;
    set_latex_headers(t, {{2, "Rank-sum\\\\test"},
                          {9, "Signed-rank\\\\test"},
                          {5, "$p$"},
                          {6, "$p$\\\\(Holm)"},
                          {8, "Paired\\\\runs"},
                          {11, "Signed-\\\\rank $z$"},
                          {12, "Signed-\\\\rank $p$"},
                          {13, "Signed-\\\\rank $p$\\\\(Holm)"}});
}

} // namespace

Table tests_table(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                  const ComparisonOptions& options) {
    Table t;
    t.id = "tests";
    t.title = "Tests against the reference " + index.label(options.reference);
    t.header = test_columns;
    for (const auto& c : comparisons)
        t.add_row(comparison_row(index, c));
    add_win_tie_loss_rows(t, index, comparisons);
    t.caption = tests_caption(index, comparisons, options);
    t.latex_note = "Each algorithm against " + index.label(options.reference) +
                   ": Holm-adjusted p of the rank-sum and signed-rank tests, effect size A12, and the marker "
                   "(Methods)." +
                   untested_note(index, options.reference) + left_out_notes(index);
    t.methods = {t.caption.substr(0, t.caption.size() - untested_note(index, options.reference).size() -
                                         left_out_notes(index).size())};
    tests_latex_layout(t);
    format_columns(t);
    return t;
}

} // namespace mhb::tables
