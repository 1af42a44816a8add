// The public part of the statistics tables of a study: the reference, the +/=/- markers and their
// w/t/l counts, and comparison_tables(), which puts together the tables that summary_table.cpp,
// tests_table.cpp, comparison_table.cpp and across_problems_table.cpp build.
#include "results/tables/comparison_tables.hpp"

#include <stdexcept>

#include "results/tables/comparison_common.hpp"

namespace mhb {

std::string win_tie_loss(const std::vector<std::string>& markers) {
    std::size_t w = 0;
    std::size_t t = 0;
    std::size_t l = 0;
    for (const auto& m : markers) {
        w += m == "+" ? 1U : 0U;
        t += m == "=" ? 1U : 0U;
        l += m == "-" ? 1U : 0U;
    }
    return std::to_string(w) + "/" + std::to_string(t) + "/" + std::to_string(l);
}

TableCell marker_cell(const std::string& marker) {
    TableCell cell = text_cell(marker);
    if (!marker.empty())
        cell.latex = "$" + marker + "$";
    return cell;
}

std::string resolve_reference(const StudyIndex& index, const std::optional<std::string>& requested) {
    const auto& algorithms = index.algorithms();
    if (algorithms.empty())
        throw std::invalid_argument("the study has no runs");
    std::string known;
    for (const auto& a : algorithms)
        known += (known.empty() ? "" : ", ") + a + (index.label(a) == a ? "" : " (" + index.label(a) + ")");
    if (!requested) {
        // The paper's ITLBO (all defaults) if the study has it, else its first ITLBO variant.
        for (const auto& a : algorithms)
            if (a == "itlbo")
                return a;
        for (const auto& a : algorithms)
            if (split_spec_text(a).name == "itlbo")
                return a;
        return algorithms.front();
    }
    for (const auto& a : algorithms)
        if (a == *requested)
            return a;
    std::vector<std::string> matches;
    for (const auto& a : algorithms)
        if (index.label(a) == *requested)
            matches.push_back(a);
    if (matches.empty())
        for (const auto& a : algorithms)
            if (split_spec_text(a).name == *requested)
                matches.push_back(a);
    if (matches.size() == 1)
        return matches.front();
    throw std::invalid_argument("--reference '" + *requested + "' " +
                                (matches.empty() ? "is not an algorithm of the study"
                                                 : "names several algorithms; give the full spec") +
                                " (the study has: " + known + ")");
}

std::string comparison_marker(double adjusted_p, double a12, double alpha) {
    if (adjusted_p >= alpha || a12 == 0.5)
        return "=";
    return a12 < 0.5 ? "+" : "-";
}

std::string signed_rank_marker(double adjusted_p, const TestResult& signed_rank, std::size_t nonzero_pairs,
                               double alpha) {
    const double n = static_cast<double>(nonzero_pairs);
    const double centred = signed_rank.statistic - n * (n + 1.0) / 4.0;
    if (adjusted_p >= alpha || centred == 0.0)
        return "=";
    return centred < 0.0 ? "+" : "-";
}

std::vector<Table> comparison_tables(const StudyIndex& index, const ComparisonOptions& options) {
    std::vector<Table> out;
    out.push_back(tables::summary_table(index, options));
    const auto comparisons = tables::compare_with_reference(index, options);
    if (!comparisons.empty())
        out.push_back(tables::tests_table(index, comparisons, options));
    out.push_back(tables::comparison_table(index, comparisons, options));
    if (auto across = tables::across_problems_table(index, options))
        out.push_back(std::move(*across));
    return out;
}

} // namespace mhb
