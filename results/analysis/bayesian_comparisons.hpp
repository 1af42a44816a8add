// The Bayesian signed-rank test (bayesian_signed_rank.hpp) of each algorithm against the reference:
// per problem on the paired runs (common seeds), and across problems on per-problem medians.
//
// The compared quantity: the log10 gap, gap_response(f, f*) of factorial_effects.hpp, where every
// run of both algorithms on the problem knows f*; the final f otherwise. The ROPE's half-width is
// in those units: `rope` decades of f - f* (0.1 by default: gaps within a factor 10^0.1 = 1.26 are
// practically equal); for raw f, `raw_rope` in units of f, and without it no ROPE (rope 0: only
// exact ties are "equivalent"), since no width of f means the same on every problem.
// Differences are reference - algorithm, so "left" is the reference better (lower), "right" the
// algorithm better. Across problems: the median of the compared quantity per problem and algorithm,
// paired by problem, on the problems where both ran; only when there are two or more such problems
// and every one is on the log10 gap scale (raw f of different problems are not one scale).
// Each test's seed is a hash of its problem (or "all problems"), algorithm and reference: a test
// gives the same probabilities whatever else the study holds.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "results/analysis/bayesian_signed_rank.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

// The default ROPE of the log10 gap, in decades (ReportOptions::rope, --rope).
inline constexpr double default_log10_rope = 0.1;

struct BayesianRope {
    double log10_gap = default_log10_rope; // decades of f - f*
    std::optional<double> raw;             // units of f, for problems without a known f*
};

struct BayesianComparison {
    std::string problem; // a problem spec, or "all problems (N)"
    std::string algorithm;
    bool across_problems = false;
    bool paired = true;         // false: the problem's runs do not pair by seed (no test)
    bool log10_gap = true;      // the compared quantity: log10(f - f*), else f
    std::optional<double> rope; // none: no ROPE (raw f without raw_rope)
    BayesianSignedRank result;  // left = reference better, right = algorithm better
};

// Every algorithm but `reference` on every problem where the reference has successful runs, in the
// index's order, then the across-problems tests. `kept_samples` theta samples are kept per test
// (for the simplex figure).
std::vector<BayesianComparison> bayesian_comparisons(const StudyIndex& index, const std::string& reference,
                                                     const BayesianRope& rope, std::size_t kept_samples);

// bayesian_probabilities.csv:
// problem,algorithm,reference,across_problems,scale,rope,pairs,p_reference_better,
// p_equivalent,p_algorithm_better,theta_reference_better,theta_equivalent,theta_algorithm_better
// (the posterior means), a row per test; and bayesian_samples.csv:
// problem,algorithm,sample,theta_reference_better,theta_equivalent,theta_algorithm_better, the kept
// samples of the tests a figure draws (the across-problems tests when there are any, else all).
std::string bayesian_csv(const StudyIndex& index, const std::string& reference,
                         const std::vector<BayesianComparison>& comparisons);
std::string bayesian_samples_csv(const StudyIndex& index, const std::vector<BayesianComparison>& comparisons);

} // namespace mhb
