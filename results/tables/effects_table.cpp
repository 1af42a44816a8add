#include "results/tables/effects_table.hpp"

#include <cctype>
#include <string>

#include "results/analysis/bayesian_signed_rank.hpp"
#include "results/table_model/latex_escape.hpp" // escaping lives beside the model

namespace mhb {

namespace {

// An effect's or design's name for LaTeX: escaped, with the " x " of an interaction as a times sign
// and 2^k as a power.
std::string latex_times(const std::string& name) {
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i) {
        if (name.compare(i, 3, " x ") == 0) {
            out += " $\\times$ ";
            i += 2;
        } else if (name.compare(i, 2, "2^") == 0) {
            std::size_t j = i + 2;
            while (j < name.size() && std::isdigit(static_cast<unsigned char>(name[j])) != 0)
                ++j;
            out += "$2^{" + name.substr(i + 2, j - i - 2) + "}$";
            i = j - 1;
        } else {
            out += latex_escape(std::string(1, name[i]));
        }
    }
    return out;
}

// One row per effect of every analysis; the problems with blocks left out or runs at +inf are
// gathered for the caption.
struct EffectNotes {
    std::vector<std::string> left_out;
    std::vector<std::string> infinite;
};
EffectNotes add_effect_rows(Table& t, const std::vector<DesignEffects>& designs) {
    EffectNotes notes;
    for (const auto& d : designs)
        for (const auto& a : d.analyses) {
            if (a.left_out > 0 && a.problems == 1)
                notes.left_out.push_back(std::to_string(a.left_out) + " on " + a.problem);
            if (a.infinite_runs > 0 && a.problems == 1)
                notes.infinite.push_back(std::to_string(a.infinite_runs) + " on " + a.problem);
            for (const auto& e : a.effects) {
                TableCell effect = text_cell(e.name);
                effect.latex = latex_times(e.name);      // "obl x stepwise" -> obl $\times$ stepwise
                TableCell test = text_cell(e.test.name); // the caption names the test; LaTeX says how
                test.latex = e.test.exact ? "exact" : "normal approx.";
                TableCell design = text_cell(d.design.description());
                design.latex = latex_times(d.design.description());
                t.add_row({design, text_cell(a.problem), text_cell(scale_name(a.scale)),
                           number_cell(static_cast<double>(a.blocks), 6), text_cell(a.paired ? "yes" : "no"),
                           effect, number_cell(e.mean, 4), number_cell(e.median, 4), test,
                           number_cell(e.test.statistic, 6), number_cell(e.test.p_value, 3),
                           number_cell(e.adjusted_p, 3), text_cell(e.reading), fixed_cell(e.p_lowers, 3),
                           fixed_cell(e.p_no_effect, 3), fixed_cell(e.p_raises, 3)});
            }
        }
    return notes;
}

// What the Bayesian columns are, with the ROPE of the log10 scale when an analysis has one.
std::string bayesian_effects_note(const std::vector<DesignEffects>& designs) {
    std::optional<double> rope;
    for (const auto& d : designs)
        for (const auto& a : d.analyses)
            rope = rope ? rope : a.rope;
    return " P(lowers f), P(no practical effect), P(raises f): the Bayesian signed-rank test (Benavoli et "
           "al. 2017, prior strength 0.5 at 0, " +
           std::to_string(bayesian_default_samples) +
           " seeded Monte Carlo samples) of the per-block effects against 0, each the posterior probability "
           "that the effect's Walsh averages lie mostly left of -ROPE, inside [-ROPE, ROPE] or right of "
           "+ROPE; ROPE " +
           (rope ? format_number(*rope, 4) + " decades on the log10 scale (--rope)" : std::string("")) +
           (rope ? "; " : "") + "none on the rank scale (only zero effects count as no effect).";
}

std::string effects_caption(const EffectNotes& notes, const std::vector<DesignEffects>& designs,
                            const std::vector<DesignCandidate>& rejected, double alpha) {
    std::string caption =
        "Variants of one algorithm forming a full 2^k factorial design over on/off switches. Response per "
        "run: "
        "log10(max(f - f*, floor)) where f* is known, floor = max(1e-300, 4 eps |f*|); otherwise the rank of "
        "f "
        "among the 2^k variants of its block (1 = lowest). A block is one (problem, run index) in which "
        "every "
        "variant has a successful run; Paired: yes when all variants of a block share its seed (common "
        "random "
        "numbers), no when seeds differ (the blocks then group independent runs). Effect per block: mean "
        "response with the switch on minus with it off, averaged over the other switches; interaction A x B: "
        "mean where A and B agree minus where they differ (half the change of A's effect when B is switched "
        "on). Negative = lower f = better. Mean and median over blocks; two-sided Wilcoxon signed-rank test "
        "of "
        "the per-block effects against 0 (V = sum of the ranks of positive effects), Holm-adjusted across "
        "the "
        "effects of each design and problem, alpha = " +
        format_number(alpha, 3) +
        ". \"All problems\" pools the blocks of every problem (log10 scale when every problem has a known "
        "optimum, ranks otherwise).";
    if (!notes.left_out.empty())
        caption +=
            " Run indices left out (a variant failed or did not run): " + join(notes.left_out, ", ") + ".";
    if (!notes.infinite.empty())
        caption +=
            " Runs that ended at +inf (kept as the worst rank; such a problem, and the pooled analysis, "
            "use the within-block rank scale, since log10(inf - f*) = inf would make every effect inf "
            "or undefined): " +
            join(notes.infinite, ", ") + ".";
    caption += bayesian_effects_note(designs);
    for (const auto& r : rejected)
        caption += " Not a full factorial: " + r.name + " (" + r.why_not + ").";
    return caption;
}

void lay_out_effects_for_latex(Table& t) {
    // LaTeX: what every row shares (the design, the scale, pairing, the test) goes to the notes; the
    // problem and the effect repeat in each part (estimates, test, reading) of a split table.
    for (const std::size_t c : {std::size_t{0}, std::size_t{2}, std::size_t{4}, std::size_t{8}})
        t.latex_column(c).fold_constant = true;
    t.latex_column(0).key = false;
    t.latex_column(1).heading = true; // the problem heads its rows
    t.latex_column(1).fold_constant = true;
    t.latex_column(5).key = true;
    t.latex_column(2).prose = true;
    t.latex_column(8).header = "Signed-rank\\\\test";
    t.latex_column(12).prose = true;
    t.latex_column(12).wrap = true;
    for (const std::size_t c : {std::size_t{3}, std::size_t{6}, std::size_t{7}})
        t.latex_column(c).group = "estimate";
    for (const std::size_t c : {std::size_t{8}, std::size_t{9}, std::size_t{10}, std::size_t{11}})
        t.latex_column(c).group = "test";
    t.latex_column(12).group = "reading";
    for (const std::size_t c : {std::size_t{13}, std::size_t{14}, std::size_t{15}})
        t.latex_column(c).group = "Bayesian signed-rank";
    t.latex_column(14).header = "P(no practical\\\\effect)";
    t.latex_column(10).header = "$p$";
    t.latex_column(11).header = "$p$\\\\(Holm)";
}

} // namespace

std::optional<Table> effects_table(const std::vector<DesignEffects>& designs,
                                   const std::vector<DesignCandidate>& rejected, double alpha) {
    Table t;
    t.id = "effects";
    t.title = "Effect of each component: main effects and two-way interactions";
    t.header = {"Design",     "Problem",  "Scale",   "Blocks",      "Paired",
                "Effect",     "Mean",     "Median",  "Test",        "V",
                "p",          "p (Holm)", "Reading", "P(lowers f)", "P(no practical effect)",
                "P(raises f)"};
    const EffectNotes notes = add_effect_rows(t, designs);
    if (t.rows.empty())
        return std::nullopt;
    t.caption = effects_caption(notes, designs, rejected, alpha);
    lay_out_effects_for_latex(t);
    format_columns(t);
    return t;
}

} // namespace mhb
