#include "results/tables/structural_bias_table.hpp"

#include "results/analysis/structural_bias.hpp"

namespace mhb {

namespace {

std::string bias_caption(const StudyIndex& index, double alpha) {
    return "Structural bias on f0 (a fresh U(0, 1) value at each evaluation, so no point is better than "
           "another): the final best points of an unbiased optimiser are uniform in [0, 1]^D. Per dimension, "
           "Kolmogorov-Smirnov (exact p) and Anderson-Darling tests of uniformity, each Holm-adjusted across "
           "the dimensions; a dimension is rejected at alpha = " +
           format_number(alpha) +
           ". Mean |x - 0.5| is 0.25 for uniform points (two-sided one-sample t-test of the runs' means); "
           "near a bound: share of coordinates within 0.01 of 0 or 1, 2% for uniform points (exact binomial "
           "test, one-sided), split into near 0 and near 1 (1% each). Verdict: no bias detected when no "
           "dimension is rejected; otherwise centre "
           "(significantly nearer the centre), bounds (significantly many coordinates near a bound, or "
           "farther from the centre) or other." +
           left_out_notes(index);
}

} // namespace

std::optional<Table> structural_bias_table(const StudyIndex& index, double alpha) {
    const std::vector<BiasAudit> audits = structural_bias_audits(index, alpha);
    if (audits.empty())
        return std::nullopt;
    bool several_problems = false;
    for (const auto& a : audits)
        several_problems = several_problems || a.problem != audits.front().problem;
    Table t;
    t.id = "structural_bias";
    t.title = "Structural bias: uniformity of the final points on f0";
    if (several_problems)
        t.header.push_back("Problem");
    for (const char* h :
         {"Algorithm", "Runs", "Dimensions", "KS rejects", "AD rejects", "Smallest Holm p", "Mean |x - 0.5|",
          "p (centre)", "Near a bound", "Near 0", "Near 1", "p (bound)", "Verdict"})
        t.header.emplace_back(h);
    for (const auto& a : audits) {
        std::vector<TableCell> row;
        if (several_problems)
            row.push_back(text_cell(a.problem));
        row.push_back(text_cell(index.label(a.algorithm)));
        row.push_back(fixed_cell(static_cast<double>(a.runs), 0));
        row.push_back(fixed_cell(static_cast<double>(a.dimensions.size()), 0));
        row.push_back(fixed_cell(static_cast<double>(a.ks_rejected), 0));
        row.push_back(fixed_cell(static_cast<double>(a.ad_rejected), 0));
        row.push_back(number_cell(a.smallest_holm_p, 2));
        row.push_back(fixed_cell(a.centre_distance, 3));
        row.push_back(number_cell(a.centre_distance_p, 2));
        row.push_back(fixed_cell(a.near_bound_share, 3));
        row.push_back(fixed_cell(a.near_lower_share, 3));
        row.push_back(fixed_cell(a.near_upper_share, 3));
        row.push_back(number_cell(a.near_bound_p, 2));
        row.push_back(text_cell(a.verdict));
        t.add_row(std::move(row));
    }
    t.caption = bias_caption(index, alpha);
    format_columns(t);
    return t;
}

} // namespace mhb
