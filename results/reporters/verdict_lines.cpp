#include "results/reporters/verdict_lines.hpp"

#include <algorithm>
#include <cmath>

#include "results/table_model/table.hpp" // format_number, join

namespace mhb {

namespace {

using Lines = std::vector<std::string>;

// A line cut to the width, "..." marking the cut.
std::string fit(const std::string& line) {
    return line.size() <= verdict_width ? line : line.substr(0, verdict_width - 3) + "...";
}

std::string padded(const std::string& text, std::size_t width) {
    const std::string cut = text.size() > width ? text.substr(0, width - 1) + "~" : text;
    return cut + std::string(width - cut.size(), ' ');
}

std::string right(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

// 15050 as "15 050", as the README writes counts.
std::string count_text(double value) {
    if (!std::isfinite(value))
        return format_number(value);
    const long long n = std::llround(value);
    const std::string digits = std::to_string(n < 0 ? -n : n);
    std::string out = n < 0 ? "-" : "";
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) // a space before each group of three from the right
            out += ' ';
        out += digits[i];
    }
    return out;
}

// The rank of position i, right-aligned in the first five columns.
std::string rank_text(std::size_t i) {
    return right(std::to_string(i + 1), 4) + " ";
}

std::string p_text(double p) {
    return "p = " + format_number(p, 2);
}

std::string versus_text(const RankedAlgorithm& entry) {
    if (entry.versus_best == VersusBest::best)
        return "best";
    return versus_best_text(entry.versus_best) + " (" + p_text(entry.adjusted_p) + ")";
}

std::string test_name(const ProblemVerdict& problem) {
    return problem.paired ? "Wilcoxon signed-rank, paired runs" : "Wilcoxon rank-sum";
}

std::size_t runs_of(const ProblemVerdict& problem) {
    std::size_t most = 0;
    for (const auto& r : problem.ranking)
        most = std::max(most, r.runs);
    return most;
}

// One problem's ranking: a heading, the column heads, a line per algorithm.
Lines problem_block(const ProblemVerdict& problem) {
    const bool gap = problem.gap_known();
    const bool evaluations = problem.evaluations_differ();
    std::string heading = problem.problem + " (" + std::to_string(runs_of(problem)) + " runs";
    if (!evaluations && !problem.ranking.empty())
        heading += ", " + count_text(problem.ranking.front().median_evaluations) + " evaluations";
    Lines out = {heading + "; vs best: " + test_name(problem) + ", Holm)",
                 "   # " + padded("algorithm", 22) + right(gap ? "median f - f*" : "median f", 14) +
                     (evaluations ? right("evaluations", 13) : "") + "   vs best"};
    for (std::size_t i = 0; i < problem.ranking.size(); ++i) {
        const RankedAlgorithm& r = problem.ranking[i];
        out.push_back(
            rank_text(i) + padded(r.label, 22) + right(format_number(gap ? *r.median_gap : r.median, 3), 14) +
            (evaluations ? right(count_text(r.median_evaluations), 13) : "") + "   " + versus_text(r));
    }
    if (!problem.without_success.empty())
        out.push_back("     no successful run: " + join(problem.without_success, ", "));
    return out;
}

// One line of a problem: its best and those not significantly different from it.
std::string problem_line(const ProblemVerdict& problem) {
    if (problem.ranking.empty())
        return "  " + problem.problem + ": no successful run";
    std::vector<std::string> tied;
    for (const auto& r : problem.ranking)
        if (r.versus_best == VersusBest::not_different || r.versus_best == VersusBest::better)
            tied.push_back(r.label);
    std::string line = "  " + problem.problem + ": " + problem.ranking.front().label;
    if (!tied.empty())
        line += "; not different: " + join(tied, ", ");
    return line;
}

// The ranking across problems, cut to `room` lines (at least its heading and column heads).
Lines across_block(const AcrossVerdict& across, std::size_t room) {
    std::string heading =
        "Across " + std::to_string(across.problems) + " problems: Friedman " + p_text(across.friedman_p);
    if (across.critical_difference)
        heading += ", critical difference " + format_number(*across.critical_difference, 3) + " ranks";
    Lines out = {heading, "   # " + padded("algorithm", 22) + right("mean rank", 10) +
                              "   problems where best/not different/worse"};
    const std::size_t n = across.ranking.size();
    const std::size_t shown = room >= n + 2 ? n : (room > 3 ? room - 3 : 0);
    for (std::size_t i = 0; i < shown; ++i) {
        const AcrossRank& r = across.ranking[i];
        std::string line = rank_text(i) + padded(r.label, 22) + right(format_number(r.mean_rank, 3), 10) +
                           "   " + std::to_string(r.best) + "/" + std::to_string(r.tied) + "/" +
                           std::to_string(r.worse);
        if (across.critical_difference)
            line += r.within_cd ? ", within CD of the best" : "";
        out.push_back(line);
    }
    if (shown < n)
        out.push_back("     ... " + std::to_string(n - shown) + " more: across_problems.md");
    return out;
}

// The Bayesian reading of a component in a few words: the region its posterior favours most,
// "   P(raises f) = 1.00" (empty when the test was not computed).
std::string bayesian_words(const ComponentVerdict& e) {
    if (e.p_lowers + e.p_no_effect + e.p_raises == 0.0)
        return "";
    const double most = std::max({e.p_lowers, e.p_no_effect, e.p_raises});
    const char* region = most == e.p_lowers ? "lowers f" : (most == e.p_raises ? "raises f" : "no effect");
    return std::string("   P(") + region + ") = " + format_fixed(most, 2);
}

// The main effects of each design on one analysis (pooled or a problem): a heading and a line each.
Lines pooled_effects_block(const std::vector<ComponentVerdict>& effects) {
    Lines out;
    std::string last;
    for (const auto& e : effects) {
        if (!e.pooled)
            continue;
        if (e.design + e.problem != last) {
            out.push_back("Components of " + e.design + ", " + e.problem + ", effect on " + e.scale + ":");
            last = e.design + e.problem;
        }
        out.push_back("    " + padded(e.component, 18) + padded(component_effect_text(e.effect), 13) +
                      right(format_number(e.mean, 3), 9) + "   " + p_text(e.adjusted_p) + " (Holm)" +
                      bayesian_words(e));
    }
    return out;
}

// Per problem, one line of what each component does.
Lines problem_effects_lines(const std::vector<ComponentVerdict>& effects) {
    Lines out;
    for (std::size_t i = 0; i < effects.size();) {
        if (effects[i].pooled) {
            ++i;
            continue;
        }
        std::string line = "  " + effects[i].problem + ":";
        const std::string key = effects[i].design + effects[i].problem;
        for (; i < effects.size() && effects[i].design + effects[i].problem == key; ++i)
            line += " " + effects[i].component + " " + component_effect_text(effects[i].effect) + ",";
        line.pop_back();
        out.push_back(line);
    }
    return out;
}

// "bounds (KS 0/30, AD 30/30 dims; |x-0.5| 0.261; near 0/1: 11.1/7.1%)": uniform is 0.25 and 1%
// near each bound (within 0.01).
std::string bias_evidence(const BiasAudit& audit) {
    const std::string dims = std::to_string(audit.dimensions.size());
    return audit.verdict + " (KS " + std::to_string(audit.ks_rejected) + "/" + dims + ", AD " +
           std::to_string(audit.ad_rejected) + "/" + dims + " dims; |x-0.5| " +
           format_fixed(audit.centre_distance, 3) +
           "; near 0/1: " + format_fixed(100.0 * audit.near_lower_share, 1) + "/" +
           format_fixed(100.0 * audit.near_upper_share, 1) + "%)";
}

void append(Lines& to, const Lines& from) {
    to.insert(to.end(), from.begin(), from.end());
}

std::string budget_heading(const BudgetVerdict& verdict) {
    return "Verdict" + (verdict.budget.empty() ? std::string() : ", budget " + verdict.budget) +
           " (alpha = " + format_number(verdict.alpha, 3) + "):";
}

// What follows the headline sections: per problem in full, or a line each, or where to look.
Lines per_problem_detail(const BudgetVerdict& verdict, std::size_t room) {
    Lines full;
    for (const auto& p : verdict.problems)
        append(full, problem_block(p));
    if (full.size() <= room)
        return full;
    Lines compact = {"Per problem: the best, and those not significantly different from it:"};
    for (const auto& p : verdict.problems)
        compact.push_back(problem_line(p));
    if (compact.size() <= room)
        return compact;
    return {"Per problem (" + std::to_string(verdict.problems.size()) +
            " problems): comparison.md and tests.md, or --tables"};
}

} // namespace

std::vector<std::string> verdict_lines(const BudgetVerdict& verdict, std::size_t max_lines) {
    Lines lines = {budget_heading(verdict)};
    if (!verdict.bias.empty()) // f0: where the final points lie, not a ranking
        lines.push_back("Structural bias on f0 (final points against uniform; uniform: |x-0.5| 0.25, 1% near "
                        "0 and near 1):");
    for (const auto& [label, audit] : verdict.bias)
        lines.push_back("  " + label + ": " + bias_evidence(audit));
    if (verdict.problems.size() == 1) {
        append(lines, problem_block(verdict.problems.front()));
    } else {
        append(lines, pooled_effects_block(verdict.effects));
        if (verdict.across) {
            const std::size_t used = lines.size() + 1; // and a line of per-problem detail
            append(lines, across_block(*verdict.across, max_lines > used ? max_lines - used : 0));
        }
        const std::size_t room = max_lines > lines.size() ? max_lines - lines.size() : 1;
        append(lines, per_problem_detail(verdict, std::max<std::size_t>(room, 1)));
        const Lines component_lines = problem_effects_lines(verdict.effects);
        if (!component_lines.empty() && lines.size() + component_lines.size() + 1 <= max_lines) {
            lines.push_back("Components per problem:");
            append(lines, component_lines);
        }
    }
    for (auto& line : lines)
        line = fit(line);
    return lines;
}

} // namespace mhb
