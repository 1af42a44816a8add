// The table "bayesian" (bayesian_table.hpp): one row per comparison, its caption the model.
#include "results/tables/bayesian_table.hpp"

#include <algorithm>

#include "results/tables/table_cells.hpp"

namespace mhb {

namespace {

std::vector<TableCell> bayesian_row(const StudyIndex& index, const BayesianComparison& c) {
    std::vector<TableCell> row = {text_cell(c.problem), text_cell(index.label(c.algorithm)),
                                  text_cell(c.log10_gap ? "log10(f - f*)" : "f"),
                                  c.rope ? number_cell(*c.rope, 4) : text_cell("no ROPE")};
    if (!c.paired) {
        row.push_back(text_cell("no (seeds differ)"));
        for (int i = 0; i < 3; ++i)
            row.push_back(tables::empty_cell());
        return row;
    }
    row.push_back(number_cell(static_cast<double>(c.result.pairs), 6));
    row.push_back(fixed_cell(c.result.left, 3)); // probabilities: three decimals align
    row.push_back(fixed_cell(c.result.rope, 3));
    row.push_back(fixed_cell(c.result.right, 3));
    return row;
}

std::string bayesian_caption(const std::vector<BayesianComparison>& comparisons, const BayesianRope& rope) {
    const bool any_raw = std::any_of(comparisons.begin(), comparisons.end(),
                                     [](const BayesianComparison& c) { return !c.log10_gap; });
    const bool any_across = std::any_of(comparisons.begin(), comparisons.end(),
                                        [](const BayesianComparison& c) { return c.across_problems; });
    std::string caption =
        "Bayesian signed-rank test (Benavoli, Corani, Demsar, Zaffalon, JMLR 18, 2017; as baycomp's "
        "SignedRankTest) of the differences reference - algorithm over the paired runs (common seeds) of "
        "each problem: a Dirichlet-process prior of strength 0.5 at 0, theta = the posterior mass of the "
        "Walsh averages left of -ROPE (the reference better), inside [-ROPE, ROPE] (equivalent) and right "
        "of +ROPE (the algorithm better); each probability is the share of " +
        std::to_string(bayesian_default_samples) +
        " Monte Carlo samples of theta in which that region's mass is the largest (a tie shared), seeded "
        "by the problem's and algorithms' names. Compared: log10(max(f - f*, floor)) where every run of "
        "both knows f*, ROPE " +
        format_number(rope.log10_gap, 4) + " decades (--rope)";
    caption += any_raw ? std::string("; the final f otherwise, ") +
                             (rope.raw ? "ROPE " + format_number(*rope.raw, 4) + " in units of f (--raw-rope)"
                                       : "with no ROPE (a width of f means nothing across problems; "
                                         "--raw-rope sets one), so only exact ties count as equivalent")
                       : std::string();
    caption += ". A probability above 0.95 is a decision; between, the data are not yet enough.";
    if (any_across)
        caption += " \"All problems\": the same test on the per-problem medians of log10(f - f*), paired by "
                   "problem.";
    if (std::any_of(comparisons.begin(), comparisons.end(),
                    [](const BayesianComparison& c) { return !c.paired; }))
        caption += " \"no (seeds differ)\": the problem's runs do not pair by seed (seeds = per-algorithm), "
                   "so there are no paired differences to test.";
    return caption;
}

} // namespace

std::optional<Table> bayesian_table(const StudyIndex& index, const std::string& reference,
                                    const std::vector<BayesianComparison>& comparisons,
                                    const BayesianRope& rope) {
    if (comparisons.empty())
        return std::nullopt;
    Table t;
    t.id = "bayesian";
    t.title = "Bayesian signed-rank tests against the reference " + index.label(reference);
    t.header = {"Problem", "Algorithm",           "Compared",      "ROPE",
                "Pairs",   "P(reference better)", "P(equivalent)", "P(algorithm better)"};
    for (const auto& c : comparisons)
        t.add_row(bayesian_row(index, c));
    t.caption = bayesian_caption(comparisons, rope) + left_out_notes(index);
    t.latex_note = "Each algorithm against " + index.label(reference) +
                   ": posterior probabilities of the Bayesian signed-rank test with a ROPE (Methods).";
    t.methods = {bayesian_caption(comparisons, rope)};
    t.latex_column(0).fold_constant = true;
    t.latex_column(0).heading = true;
    t.latex_column(1).key = true;
    t.latex_column(2).fold_constant = true;
    t.latex_column(3).fold_constant = true;
    tables::set_latex_headers(t, {{5, "P(reference\\\\better)"}, {7, "P(algorithm\\\\better)"}});
    format_columns(t);
    return t;
}

} // namespace mhb
