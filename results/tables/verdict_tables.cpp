#include "results/tables/verdict_tables.hpp"

#include <algorithm>
#include <optional>

#include "results/tables/table_cells.hpp"

namespace mhb {

namespace {

std::string alpha_phrase(const BudgetVerdict& verdict) {
    return "alpha = " + format_number(verdict.alpha, 3);
}

std::optional<Table> across_table(const BudgetVerdict& verdict) {
    if (!verdict.across)
        return std::nullopt;
    const AcrossVerdict& across = *verdict.across;
    Table t;
    t.id = "verdict_across";
    t.title = "Verdict across " + std::to_string(across.problems) + " problems";
    t.header = {"Rank", "Algorithm", "Mean rank", "Best on", "Not different on", "Worse on"};
    if (across.critical_difference)
        t.header.push_back("Within CD of the best");
    for (std::size_t i = 0; i < across.ranking.size(); ++i) {
        const AcrossRank& r = across.ranking[i];
        std::vector<TableCell> row = {number_cell(static_cast<double>(i + 1), 6),
                                      text_cell(r.label),
                                      number_cell(r.mean_rank, 3),
                                      number_cell(static_cast<double>(r.best), 6),
                                      number_cell(static_cast<double>(r.tied), 6),
                                      number_cell(static_cast<double>(r.worse), 6)};
        if (across.critical_difference)
            row.push_back(text_cell(r.within_cd ? "yes" : "no"));
        row[1].bold = i == 0;
        t.add_row(std::move(row));
    }
    t.caption =
        "Friedman average ranks of the per-problem median final values (rank 1 = lowest), over the " +
        std::to_string(across.problems) +
        " problems on which every algorithm ran; Friedman p = " + format_number(across.friedman_p, 3) +
        ". Best on / not different on / worse on: the problems " +
        "on which the algorithm has the lowest median, is not significantly different from the " +
        "algorithm that has it, or is significantly worse (Wilcoxon signed-rank test of paired runs, " +
        "rank-sum test where runs are not paired; Holm across each problem's comparisons, " +
        alpha_phrase(verdict) + ").";
    if (across.critical_difference)
        t.caption +=
            " Nemenyi critical difference (Demsar 2006): " + format_number(*across.critical_difference, 3) +
            " ranks.";
    format_columns(t);
    return t;
}

std::optional<Table> effects_verdict_table(const BudgetVerdict& verdict) {
    if (verdict.effects.empty())
        return std::nullopt;
    Table t;
    t.id = "verdict_effects";
    t.title = "Verdict on each component";
    t.header = {"Design", "Problem", "Component", "Verdict", "Mean effect", "p (Holm)", "Response"};
    // The Bayesian reading beside the test, where it was computed (bayesian_effects.hpp).
    const auto computed = [](const ComponentVerdict& e) {
        return e.p_lowers + e.p_no_effect + e.p_raises > 0;
    };
    const bool bayesian = std::any_of(verdict.effects.begin(), verdict.effects.end(), computed);
    if (bayesian)
        t.header.insert(t.header.end(), {"P(lowers f)", "P(no effect)", "P(raises f)"});
    for (const auto& e : verdict.effects) {
        std::vector<TableCell> row = {text_cell(e.design),    text_cell(e.problem),
                                      text_cell(e.component), text_cell(component_effect_text(e.effect)),
                                      number_cell(e.mean, 3), number_cell(e.adjusted_p, 2),
                                      text_cell(e.scale)};
        row[3].bold = e.effect == ComponentEffect::helps || e.effect == ComponentEffect::hurts;
        if (bayesian)
            for (const double p : {e.p_lowers, e.p_no_effect, e.p_raises})
                row.push_back(computed(e) ? fixed_cell(p, 2) : tables::empty_cell());
        t.add_row(std::move(row));
    }
    t.caption =
        "Main effect of each switch: mean over blocks of the response with the switch on minus off "
        "(negative: lower f, the component helps); Wilcoxon signed-rank test of the per-block effects "
        "against 0, Holm across the effects of one design and problem, " +
        alpha_phrase(verdict) + ". Interactions: the effects table." +
        (bayesian ? " P(...): the Bayesian signed-rank test of the same per-block effects with its ROPE (the "
                    "bayesian table's method)."
                  : "");
    format_columns(t);
    return t;
}

Table problems_table(const BudgetVerdict& verdict) {
    Table t;
    t.id = "verdict";
    t.title = "Verdict per problem";
    t.header = {"Problem", "Rank",     "Algorithm", "Median f - f*", "Median f", "Evaluations (median)",
                "vs best", "p (Holm)", "Test"};
    for (const auto& p : verdict.problems)
        for (std::size_t i = 0; i < p.ranking.size(); ++i) {
            const RankedAlgorithm& r = p.ranking[i];
            std::vector<TableCell> row = {
                text_cell(p.problem),
                number_cell(static_cast<double>(i + 1), 6),
                text_cell(r.label),
                r.median_gap ? number_cell(*r.median_gap, 3) : text_cell(""),
                number_cell(r.median, 5),
                fixed_cell(r.median_evaluations, 0),
                text_cell(versus_best_text(r.versus_best)),
                i == 0 ? text_cell("") : number_cell(r.adjusted_p, 2),
                text_cell(i == 0 ? "" : (p.paired ? "signed-rank (paired)" : "rank-sum"))};
            row[2].bold = i == 0;
            t.add_row(std::move(row));
        }
    t.caption =
        "Per problem, the algorithms by median final value (ties by the mean), each against the best: "
        "two-sided Wilcoxon signed-rank test of the paired differences where runs are paired by seed, "
        "rank-sum test otherwise; Holm across each problem's comparisons, " +
        alpha_phrase(verdict) + ". Better in pairs: the paired runs favour it although its median is higher.";
    format_columns(t);
    return t;
}

} // namespace

std::vector<Table> verdict_tables(const BudgetVerdict& verdict) {
    std::vector<Table> tables;
    if (auto t = across_table(verdict))
        tables.push_back(std::move(*t));
    if (auto t = effects_verdict_table(verdict))
        tables.push_back(std::move(*t));
    if (!verdict.problems.empty())
        tables.push_back(problems_table(verdict));
    return tables;
}

} // namespace mhb
