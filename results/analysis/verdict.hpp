// The verdict of one budget: who won on each problem, who wins across problems, and what each
// component of a factorial design does -- what a reader wants before any table (issue 37). The
// console prints it after `mhbench run` and `mhbench report` (results/reporters/verdict_lines.hpp)
// and the HTML page opens with it (results/tables/verdict_tables.hpp); the full tables stay in
// files.
//
// The ranking is the report's: on a problem, the algorithms by median final value (the lowest in
// bold in the comparison table), ties broken by the mean, then by study order. Each is tested
// against the best with the test the report's markers use: the Wilcoxon signed-rank test of the
// paired differences where the problem's runs are paired by seed (common random numbers), the
// rank-sum test otherwise; Holm across the problem's comparisons; the same alpha as the tables.
// Across problems: Friedman average ranks of the per-problem medians (the across_problems table's
// ranks and blocks), the Friedman p-value, the Nemenyi critical difference where Demsar's table
// has one, and each algorithm's count of problems where it is the best, not significantly
// different from the best, or worse. Factorial designs: each main effect's reading from
// factorial_effects (helps, hurts, no evidence), pooled over problems and per problem. f0 problems
// get the structural-bias audit (structural_bias.hpp) instead of a ranking and effects.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "results/analysis/factorial_effects.hpp"
#include "results/analysis/structural_bias.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

// An algorithm against the best of its problem.
enum class VersusBest {
    best,          // rank 1
    not_different, // no significant difference after Holm
    worse,         // significantly worse (higher values)
    better,        // significant the other way: the median ranks it lower, the paired runs favour it
};

struct RankedAlgorithm {
    std::string algorithm; // the spec
    std::string label;
    std::size_t runs = 0;             // successful runs
    double median = 0.0;              // median final value
    double mean = 0.0;                // mean final value (breaks ties of the median)
    std::optional<double> median_gap; // median of f - f*, where every run's f* is known
    double median_evaluations = 0.0;
    VersusBest versus_best = VersusBest::best;
    double adjusted_p = 1.0; // Holm-adjusted p-value of the test against the best (1 for the best)
};

struct ProblemVerdict {
    std::string problem;
    bool paired = false;                  // signed-rank test of paired runs; rank-sum otherwise
    std::vector<RankedAlgorithm> ranking; // best first
    // Algorithms that ran on the problem without one successful run, by label.
    std::vector<std::string> without_success;

    // Whether every ranked algorithm has a median gap f - f* (the problem's optimum is known).
    [[nodiscard]] bool gap_known() const;
    // Whether the algorithms spent different evaluations (an iteration budget: say how many).
    [[nodiscard]] bool evaluations_differ() const;
};

struct AcrossRank {
    std::string algorithm;
    std::string label;
    double mean_rank = 0.0; // Friedman average rank of the per-problem medians
    std::size_t best = 0;   // problems where it ranks first
    std::size_t tied = 0;   // not significantly different from the best (or better in pairs)
    std::size_t worse = 0;  // significantly worse than the best
    bool within_cd = false; // its mean rank lies within the critical difference of the best one's
};

struct AcrossVerdict {
    std::size_t problems = 0; // the blocks: problems on which every algorithm has runs
    double friedman_p = 1.0;
    std::optional<double> critical_difference; // Nemenyi, where Demsar's table has q_alpha
    std::vector<AcrossRank> ranking;           // by mean rank, best first
};

enum class ComponentEffect { helps, hurts, no_evidence, unclear };

// A main effect of one switch of a factorial design, on one problem or pooled.
struct ComponentVerdict {
    std::string design;  // "itlbo: obl x stepwise x tutorial (2^3)"
    std::string problem; // a problem spec, or "all problems (N)"
    bool pooled = false;
    std::string component; // "tutorial"
    double mean = 0.0;     // mean effect on the response (negative: lower f)
    std::string scale;     // "log10(f - f*)" or "within-block rank"
    double adjusted_p = 1.0;
    ComponentEffect effect = ComponentEffect::no_evidence;
    // The Bayesian signed-rank test of the same per-block effects (bayesian_effects.hpp); all 0
    // when it was not computed.
    double p_lowers = 0.0;
    double p_no_effect = 0.0;
    double p_raises = 0.0;
};

struct BudgetVerdict {
    std::string budget;
    double alpha = 0.05;
    std::vector<ProblemVerdict> problems;
    std::optional<AcrossVerdict> across; // two or more problems on which every algorithm ran
    std::vector<ComponentVerdict> effects;
    // f0 problems are not ranked (no point is better than another): each algorithm's
    // structural-bias audit instead, with its label.
    std::vector<std::pair<std::string, BiasAudit>> bias;
};

// The verdict of the index's budget; `designs` are its factorial designs with their effects.
BudgetVerdict budget_verdict(const StudyIndex& index, double alpha,
                             const std::vector<DesignEffects>& designs);

// "best", "not different", "worse", "better in pairs"; "helps", "hurts", "no evidence", "unclear".
std::string versus_best_text(VersusBest versus);
std::string component_effect_text(ComponentEffect effect);

} // namespace mhb
