// The tests against the reference that the comparison tables share, and the cells and caption
// phrases that describe them.
#include "results/tables/comparison_common.hpp"

#include <algorithm>

namespace mhb::tables {

namespace {

// Every value of x and y is the same one (+inf included).
bool all_equal(const std::vector<double>& x, const std::vector<double>& y) {
    const double first = x.empty() ? (y.empty() ? 0.0 : y.front()) : x.front();
    const auto same = [first](double v) { return v == first; };
    return std::all_of(x.begin(), x.end(), same) && std::all_of(y.begin(), y.end(), same);
}

// One algorithm's group against the reference's, before the Holm adjustment; `nonzero` gets the
// number of paired differences that are not zero (what the signed-rank marker weighs).
Comparison compare_group(const std::string& problem, const std::string& algorithm, bool paired,
                         const RunGroup& group, const RunGroup& reference, std::size_t& nonzero) {
    const auto x = group.final_values();
    const auto y = reference.final_values();
    Comparison c{problem, algorithm, rank_sum_test(x, y), 1.0, vargha_delaney_a12(x, y),
                 paired,  0,         TestResult{},        1.0, ""};
    c.every_value_tied = all_equal(x, y);
    std::size_t differing = 0;
    if (paired) {
        const PairedValues pairs = paired_final_values(group, reference);
        c.pairs = pairs.x.size();
        c.paired_test = signed_rank_test(pairs.x, pairs.y);
        for (std::size_t i = 0; i < pairs.x.size(); ++i)
            differing += pairs.x[i] != pairs.y[i] ? 1U : 0U;
    }
    c.every_difference_zero = paired && differing == 0;
    nonzero = differing;
    return c;
}

// Holm across one problem's comparisons (its family), and the markers from the adjusted p-values.
void adjust_family(std::vector<Comparison>& family, const std::vector<std::size_t>& nonzero, bool paired,
                   double alpha) {
    std::vector<double> raw;
    std::vector<double> paired_raw;
    for (const auto& c : family) {
        raw.push_back(c.test.p_value);
        paired_raw.push_back(c.paired_test.p_value);
    }
    const auto adjusted = holm_adjust(raw);
    const auto paired_adjusted = holm_adjust(paired_raw);
    for (std::size_t i = 0; i < family.size(); ++i) {
        family[i].adjusted_p = adjusted[i];
        family[i].paired_adjusted_p = paired_adjusted[i];
        family[i].marker =
            paired ? signed_rank_marker(paired_adjusted[i], family[i].paired_test, nonzero[i], alpha)
                   : comparison_marker(adjusted[i], family[i].a12, alpha);
    }
}

} // namespace

std::vector<Comparison> compare_with_reference(const StudyIndex& index, const ComparisonOptions& options) {
    std::vector<Comparison> all;
    for (const auto& p : index.problems()) {
        const RunGroup* reference = index.find(p, options.reference);
        if (reference == nullptr)
            continue;
        const bool paired = index.paired(p);
        std::vector<Comparison> family;
        std::vector<std::size_t> nonzero;
        for (const auto& a : index.algorithms_on(p)) {
            if (a == options.reference)
                continue;
            nonzero.push_back(0);
            family.push_back(compare_group(p, a, paired, *index.find(p, a), *reference, nonzero.back()));
        }
        adjust_family(family, nonzero, paired, options.alpha);
        all.insert(all.end(), family.begin(), family.end());
    }
    return all;
}

std::string alpha_text(double alpha) {
    return format_number(alpha, 3);
}

TableCell test_cell(const TestResult& test) {
    TableCell cell = text_cell(test.name);
    const std::size_t comma = test.name.find(", ");
    const std::string variant = comma == std::string::npos ? "" : test.name.substr(comma + 2);
    cell.latex =
        variant.empty() ? "---" : (variant.rfind("normal approx.", 0) == 0 ? "normal approx." : variant);
    return cell;
}

std::string degenerate_tests_note(const std::vector<Comparison>& comparisons) {
    std::size_t tied = 0;
    std::size_t zero = 0;
    for (const auto& c : comparisons) {
        tied += c.every_value_tied ? 1U : 0U;
        zero += c.every_difference_zero ? 1U : 0U;
    }
    std::string note;
    if (tied > 0)
        note += " In " + std::to_string(tied) + (tied == 1 ? " comparison" : " comparisons") +
                " every value of both samples is the same: the rank-sum test has no variance there (R's "
                "wilcox.test gives p = NaN); shown as z = 0, p = 1, =.";
    if (zero > 0)
        note += " In " + std::to_string(zero) + (zero == 1 ? " comparison" : " comparisons") +
                " every paired difference is zero: the signed-rank test has nothing to rank (R gives V = 0, "
                "p = NaN); shown as V = 0, p = 1, =.";
    return note;
}

} // namespace mhb::tables
