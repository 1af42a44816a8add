// The effect of each component: for the algorithms of a study (one budget) whose variants form a
// full 2^k factorial design over on/off switches, the main effect of every switch and every
// two-way interaction, estimated within paired blocks and tested with the Wilcoxon signed-rank
// test (Holm across the effects).
//
// Design: variants of one algorithm (same name) whose full specs (every parameter, defaults
// included) differ only in k >= 1 parameters whose values are all "on"/"off", with each of the
// 2^k combinations present exactly once. Detected from algorithms.csv's full specs, so a grid
// such as itlbo:tutorial={on,off},stepwise={on,off},obl={on,off} is recognised whatever labels
// its variants carry.
//
// Response of a run: log10(max(f - f*, floor)) where the problem's optimum f* is known, with
// floor = max(1e-300, 4 ulp(|f*|)) = max(1e-300, 4 eps |f*|) (a gap below what doubles resolve
// near f*, or a negative one from rounding, is "at the optimum"); otherwise the rank of f among the
// 2^k variants of its block (1 = lowest f, ties share their mean rank).
// Infinite values: a problem on which any run of a kept block ended at +inf (a legal, worst value)
// is analysed on the rank scale, where +inf is simply the worst rank (ties with another +inf);
// log10(inf) = inf would make every effect it touches inf or NaN, and leaving those blocks out
// would hide exactly the runs a component failed to rescue. The pooled analysis then uses ranks
// too. The caption counts such runs per problem.
// Block: one (problem, run index) in which all 2^k variants have a successful run; other run
// indices (a variant failed) are left out (and counted). With common random numbers all variants of a
// block start from the same seed, so an effect is a paired difference.
// Effect in a block: mean response of the variants where the contrast is + minus the mean where
// it is -, i.e. averaged over the other factors. Main effect of A: A on (+) vs off (-);
// interaction AB: the product of the signs (+ where A and B agree), which equals half of
// (effect of A with B on - effect of A with B off). Negative = lower f = better.
// Across blocks: mean and median effect; Wilcoxon signed-rank test of the per-block effects
// against 0 (hypothesis_tests.hpp: exact below 50 blocks without ties or zeros, as R); Holm across
// the k + k(k-1)/2 effects of one (design, problem); and a plain reading.
// "All problems" pools the blocks of every problem of the budget (log10 scale when every problem
// has a known optimum, ranks on every problem otherwise).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "results/analysis/hypothesis_tests.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

struct FactorialDesign {
    std::string name;                    // the algorithm's name, e.g. "itlbo"
    std::vector<std::string> factors;    // the varying on/off parameters, sorted by name
    std::vector<std::string> algorithms; // 2^k specs; variant m has factor j on iff bit j of m is set
    [[nodiscard]] std::string description() const; // "itlbo: obl x stepwise x tutorial (2^3)"
};

// The outcome of checking one group of same-name variants.
struct DesignCandidate {
    std::string name;
    std::optional<FactorialDesign> design;
    std::string why_not; // when there is no design: which rule failed
};

// Checks whether `algorithms` (specs) with their `full_specs` (same order) form one full 2^k
// factorial design over on/off switches (see the file comment).
DesignCandidate detect_factorial_design(const std::vector<std::string>& algorithms,
                                        const std::vector<std::string>& full_specs);

// Every group of two or more variants of one algorithm name in the index, checked; in study order.
std::vector<DesignCandidate> find_factorial_designs(const StudyIndex& index);

enum class ResponseScale { log10_gap, rank };
std::string scale_name(ResponseScale scale); // "log10(f - f*)" or "within-block rank"

// The floor under which a gap f - f* counts as zero, and the response log10(max(f - f*, floor)).
double gap_floor(double f_opt);
double gap_response(double f, double f_opt);

// What an effect's test says: no significant effect, the switch on lowers or raises the response,
// or significant with the mean and the signed ranks pointing opposite ways.
enum class EffectDirection { none, lowers, raises, disagree };

struct EffectEstimate {
    std::string name;                 // "tutorial", or "stepwise x tutorial" for an interaction
    std::vector<std::size_t> factors; // one index (main effect) or two (interaction) into factors
    std::vector<double> per_block;
    double mean = 0.0;
    double median = 0.0;
    TestResult test; // Wilcoxon signed-rank of the per-block effects against 0
    double adjusted_p = 1.0;
    EffectDirection direction = EffectDirection::none;
    std::string reading; // `direction` in words
    // The Bayesian signed-rank test of the per-block effects against 0 with the analysis' ROPE
    // (bayesian_effects.hpp; 0 until add_bayesian_effects): the switch (or interaction) lowers the
    // response by more than the ROPE, changes it by less, raises it by more.
    double p_lowers = 0.0;
    double p_no_effect = 0.0;
    double p_raises = 0.0;
};

// Mean response (over blocks) of the variants at one level of a factor, or at one pair of levels
// of two factors (second_factor set).
struct LevelMean {
    std::size_t factor = 0;
    bool level = false;
    std::optional<std::size_t> second_factor;
    bool second_level = false;
    double mean = 0.0;
};

struct EffectAnalysis {
    std::string problem; // a problem spec, or "all problems (N)"
    std::size_t problems = 1;
    ResponseScale scale = ResponseScale::rank;
    std::size_t blocks = 0;
    std::size_t left_out = 0;            // run indices without a successful run of every variant
    std::size_t infinite_runs = 0;       // runs of the kept blocks that ended at +inf (or -inf)
    bool paired = false;                 // every problem's runs paired by seed (common random numbers)
    std::vector<EffectEstimate> effects; // k main effects, then the k(k-1)/2 interactions
    std::optional<double> rope;          // of the Bayesian readings: none on the rank scale
    std::vector<LevelMean> level_means;
};

// The analysis of given blocks: blocks[b][m] is the response of variant m (bit j = factor j on)
// in block b; every block has 2^factors.size() responses.
EffectAnalysis analyse_factorial_blocks(const std::vector<std::vector<double>>& blocks,
                                        const std::vector<std::string>& factors, ResponseScale scale,
                                        double alpha);

// Per problem of the index (those with at least one block), then over all problems when there are
// two or more.
std::vector<EffectAnalysis> factorial_effects(const StudyIndex& index, const FactorialDesign& design,
                                              double alpha);

struct DesignEffects {
    FactorialDesign design;
    std::vector<EffectAnalysis> analyses;
};

// effect_means.csv: design,problem,scale,blocks,factor,level,factor2,level2,mean_response
// (factor2/level2 empty for a main-effect row): the points of the main-effects and interaction plots.
std::string effect_means_csv(const std::vector<DesignEffects>& designs);

} // namespace mhb
