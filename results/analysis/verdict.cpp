#include "results/analysis/verdict.hpp"

#include <algorithm>
#include <cmath>

#include "results/analysis/critical_difference.hpp"
#include "results/analysis/hypothesis_tests.hpp"
#include "results/analysis/problem_medians.hpp"
#include "results/analysis/statistics.hpp"

namespace mhb {

namespace {

RankedAlgorithm ranked_entry(const StudyIndex& index, const RunGroup& group) {
    RankedAlgorithm entry;
    entry.algorithm = group.algorithm;
    entry.label = index.label(group.algorithm);
    entry.runs = group.runs.size();
    const std::vector<double> values = group.final_values();
    const Summary s = summarize(values);
    entry.median = s.median;
    entry.mean = s.mean;
    std::vector<double> gaps;
    std::vector<double> evaluations;
    for (const RunRecord* r : group.runs) {
        if (const auto e = r->error())
            gaps.push_back(*e);
        evaluations.push_back(static_cast<double>(r->evaluations));
    }
    if (!gaps.empty() && gaps.size() == group.runs.size())
        entry.median_gap = median_of(gaps);
    entry.median_evaluations = median_of(evaluations);
    return entry;
}

// The lower median first; a tie by the lower mean (NaN, from +inf and -inf, last), then study order
// (a stable sort keeps it).
bool ranks_before(const RankedAlgorithm& a, const RankedAlgorithm& b) {
    if (a.median != b.median)
        return a.median < b.median;
    if (std::isnan(a.mean) || std::isnan(b.mean))
        return !std::isnan(a.mean) && std::isnan(b.mean);
    return a.mean < b.mean;
}

// The raw p-value of `group` against the best, and whether its values lie higher (the side of the
// statistic's null mean, as the tables' markers read it).
std::pair<double, bool> test_against_best(const RunGroup& group, const RunGroup& best, bool paired) {
    if (paired) {
        const PairedValues pairs = paired_final_values(group, best);
        if (pairs.x.empty())
            return {1.0, false};
        const TestResult t = signed_rank_test(pairs.x, pairs.y);
        double nonzero = 0.0;
        for (std::size_t i = 0; i < pairs.x.size(); ++i)
            nonzero += pairs.x[i] != pairs.y[i] ? 1.0 : 0.0;
        return {t.p_value, t.statistic > nonzero * (nonzero + 1.0) / 4.0};
    }
    const std::vector<double> x = group.final_values();
    const std::vector<double> y = best.final_values();
    return {rank_sum_test(x, y).p_value, vargha_delaney_a12(x, y) > 0.5};
}

// Each algorithm but the best against it, Holm-adjusted across the problem's comparisons.
void test_ranking(const StudyIndex& index, ProblemVerdict& verdict, double alpha) {
    const RunGroup& best = *index.find(verdict.problem, verdict.ranking.front().algorithm);
    std::vector<double> raw;
    std::vector<bool> higher;
    for (std::size_t i = 1; i < verdict.ranking.size(); ++i) {
        const auto [p, up] = test_against_best(*index.find(verdict.problem, verdict.ranking[i].algorithm),
                                               best, verdict.paired);
        raw.push_back(std::isnan(p) ? 1.0 : p); // a degenerate test: no evidence either way
        higher.push_back(up);
    }
    const std::vector<double> adjusted = holm_adjust(raw);
    for (std::size_t i = 1; i < verdict.ranking.size(); ++i) {
        RankedAlgorithm& entry = verdict.ranking[i];
        entry.adjusted_p = adjusted[i - 1];
        entry.versus_best = !(entry.adjusted_p < alpha) ? VersusBest::not_different
                            : higher[i - 1]             ? VersusBest::worse
                                                        : VersusBest::better;
    }
}

ProblemVerdict problem_verdict(const StudyIndex& index, const std::string& problem, double alpha) {
    ProblemVerdict verdict;
    verdict.problem = problem;
    verdict.paired = index.paired(problem);
    for (const auto& a : index.algorithms()) {
        if (const RunGroup* g = index.find(problem, a))
            verdict.ranking.push_back(ranked_entry(index, *g));
        else if (index.group(problem, a) != nullptr)
            verdict.without_success.push_back(index.label(a));
    }
    std::stable_sort(verdict.ranking.begin(), verdict.ranking.end(), ranks_before);
    if (verdict.ranking.size() > 1)
        test_ranking(index, verdict, alpha);
    return verdict;
}

std::optional<AcrossVerdict> across_verdict(const StudyIndex& index,
                                            const std::vector<ProblemVerdict>& problems, double alpha) {
    const auto blocks = per_problem_medians(index);
    if (!blocks)
        return std::nullopt;
    const FriedmanResult friedman = friedman_test(blocks->second);
    AcrossVerdict across;
    across.problems = blocks->first.size();
    across.friedman_p = friedman.p_value;
    across.critical_difference =
        nemenyi_critical_difference(index.algorithms().size(), across.problems, alpha);
    for (std::size_t j = 0; j < index.algorithms().size(); ++j) {
        AcrossRank rank;
        rank.algorithm = index.algorithms()[j];
        rank.label = index.label(rank.algorithm);
        rank.mean_rank = friedman.average_ranks[j];
        for (const auto& p : problems)
            for (std::size_t i = 0; i < p.ranking.size(); ++i)
                if (p.ranking[i].algorithm == rank.algorithm) {
                    const VersusBest v = p.ranking[i].versus_best;
                    rank.best += v == VersusBest::best ? 1U : 0U;
                    rank.worse += v == VersusBest::worse ? 1U : 0U;
                    rank.tied += v == VersusBest::not_different || v == VersusBest::better ? 1U : 0U;
                }
        across.ranking.push_back(rank);
    }
    std::stable_sort(across.ranking.begin(), across.ranking.end(),
                     [](const AcrossRank& a, const AcrossRank& b) { return a.mean_rank < b.mean_rank; });
    for (auto& rank : across.ranking)
        rank.within_cd = across.critical_difference &&
                         rank.mean_rank - across.ranking.front().mean_rank <= *across.critical_difference;
    return across;
}

// A main effect's direction as a verdict: lowering the response (f or its rank) helps.
ComponentEffect component_effect(EffectDirection direction) {
    switch (direction) {
    case EffectDirection::lowers:
        return ComponentEffect::helps;
    case EffectDirection::raises:
        return ComponentEffect::hurts;
    case EffectDirection::none:
        return ComponentEffect::no_evidence;
    case EffectDirection::disagree:
        return ComponentEffect::unclear;
    }
    return ComponentEffect::unclear;
}

std::vector<ComponentVerdict> component_verdicts(const std::vector<DesignEffects>& designs) {
    std::vector<ComponentVerdict> out;
    for (const auto& d : designs)
        for (const auto& analysis : d.analyses)
            for (const auto& e : analysis.effects) {
                if (e.factors.size() != 1 || is_bias_problem(analysis.problem))
                    continue; // interactions stay in the effects table
                ComponentVerdict c;
                c.design = d.design.description();
                c.problem = analysis.problem;
                c.pooled = analysis.problems > 1;
                c.component = e.name;
                c.mean = e.mean;
                c.scale = scale_name(analysis.scale);
                c.adjusted_p = e.adjusted_p;
                c.effect = component_effect(e.direction);
                c.p_lowers = e.p_lowers;
                c.p_no_effect = e.p_no_effect;
                c.p_raises = e.p_raises;
                out.push_back(c);
            }
    // The pooled verdict first: the one line per component a reader wants before the problems'.
    std::stable_partition(out.begin(), out.end(), [](const ComponentVerdict& c) { return c.pooled; });
    return out;
}

} // namespace

bool ProblemVerdict::gap_known() const {
    return !ranking.empty() && std::all_of(ranking.begin(), ranking.end(),
                                           [](const RankedAlgorithm& r) { return r.median_gap.has_value(); });
}

bool ProblemVerdict::evaluations_differ() const {
    return std::any_of(ranking.begin(), ranking.end(), [&](const RankedAlgorithm& r) {
        return r.median_evaluations != ranking.front().median_evaluations;
    });
}

BudgetVerdict budget_verdict(const StudyIndex& index, double alpha,
                             const std::vector<DesignEffects>& designs) {
    BudgetVerdict verdict;
    verdict.budget = index.budget();
    verdict.alpha = alpha;
    for (const auto& p : index.problems())
        if (!is_bias_problem(p))
            verdict.problems.push_back(problem_verdict(index, p, alpha));
    for (auto& audit : structural_bias_audits(index, alpha))
        verdict.bias.emplace_back(index.label(audit.algorithm), std::move(audit));
    verdict.across = across_verdict(index, verdict.problems, alpha);
    verdict.effects = component_verdicts(designs);
    return verdict;
}

std::string versus_best_text(VersusBest versus) {
    switch (versus) {
    case VersusBest::best:
        return "best";
    case VersusBest::not_different:
        return "not different";
    case VersusBest::worse:
        return "worse";
    case VersusBest::better:
        return "better in pairs";
    }
    return "";
}

std::string component_effect_text(ComponentEffect effect) {
    switch (effect) {
    case ComponentEffect::helps:
        return "helps";
    case ComponentEffect::hurts:
        return "hurts";
    case ComponentEffect::no_evidence:
        return "no evidence";
    case ComponentEffect::unclear:
        return "unclear";
    }
    return "";
}

} // namespace mhb
