// The structural-bias audit (Kononova et al. 2015, "Structural bias in population-based
// algorithms", Inf. Sci. 298): on f0, where every evaluation returns a fresh U(0, 1) value
// (problems/functions/f0.cpp), no point is better than another, so an optimiser without bias ends
// its runs at points uniform in [0, 1]^D. Per algorithm, the final best points of its runs (best_x
// in runs.csv) are tested coordinate by coordinate:
//  - Kolmogorov-Smirnov and Anderson-Darling against U(0, 1) in each dimension
//    (uniformity_tests.hpp), each test's D p-values Holm-adjusted across the dimensions;
//  - where the points lie: the mean distance from the centre, |x - 0.5| (uniform: 0.25), by a
//    two-sided one-sample t-test of the runs' means over their coordinates (a run's coordinates
//    may be dependent; its runs are not); and the share of coordinates within 0.01 of a bound
//    (uniform: 0.02), by the exact binomial test P(X >= k) over all runs x dimensions.
// The classification, at the report's alpha:
//  - "no bias detected": no dimension's Holm-adjusted p is below alpha, in either test;
//  - otherwise "centre" when the points are significantly nearer the centre (t-test p < alpha,
//    mean distance below 0.25) and show no sign of the bounds; "bounds" when significantly many
//    coordinates lie near a bound (binomial p < alpha) or the points are significantly farther
//    from the centre than 0.25, and no sign of the centre; "other" for any other non-uniformity
//    (a cluster off the centre, one side of the box, or both signs at once).
// A coordinate outside [0, 1] (an optimiser that does not repair its points) is counted at the
// nearest bound. A problem is audited when its spec's family is f0: results/ sees spec texts only.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "results/analysis/uniformity_tests.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

// What counts as "at a bound", and the share of coordinates a uniform distribution puts there.
inline constexpr double bias_bound_width = 0.01;
inline constexpr double uniform_bound_share = 2.0 * bias_bound_width;
// The mean of |x - 0.5| for x ~ U(0, 1).
inline constexpr double uniform_centre_distance = 0.25;

struct DimensionUniformity {
    UniformityTest ks;
    UniformityTest ad;
    double ks_holm_p = 1; // Holm-adjusted across the dimensions
    double ad_holm_p = 1;
};

struct BiasAudit {
    std::string problem;
    std::string algorithm;
    std::size_t runs = 0; // final points audited
    std::vector<DimensionUniformity> dimensions;
    std::size_t ks_rejected = 0; // dimensions with a Holm-adjusted p below alpha
    std::size_t ad_rejected = 0;
    double smallest_holm_p = 1;
    double centre_distance = std::numeric_limits<double>::quiet_NaN(); // mean |x - 0.5|
    double centre_distance_p = 1;                                      // t-test against 0.25
    double near_bound_share = std::numeric_limits<double>::quiet_NaN();
    // Of near_bound_share, the coordinates within bias_bound_width of 0 and of 1: which bound pulls.
    double near_lower_share = std::numeric_limits<double>::quiet_NaN();
    double near_upper_share = std::numeric_limits<double>::quiet_NaN();
    double near_bound_p = 1; // binomial, against 0.02
    std::string verdict;     // "no bias detected", "centre", "bounds" or "other"
};

// Whether a problem spec is f0's ("f0" or "f0:dim=30").
bool is_bias_problem(const std::string& problem_spec);

// The audit of one algorithm's final points (points[run][dimension], all of one dimension, at
// least two runs). Throws std::invalid_argument otherwise.
BiasAudit audit_final_points(const std::vector<std::vector<double>>& points, double alpha);

// Every (f0 problem, algorithm) of the budget with at least two successful runs, in study order;
// empty when the budget has no f0 problem.
std::vector<BiasAudit> structural_bias_audits(const StudyIndex& index, double alpha);

// The final points of the runs on f0 problems, one coordinate a row: problem,algorithm,run,
// dimension,x (algorithm as its label, dimension from 1): what the bias figure draws. None when the
// budget has no f0 problem.
std::optional<std::string> final_points_csv(const StudyIndex& index);

// Every per-dimension test of the audits, one dimension a row: problem,algorithm,runs,dimension,
// ks_statistic,ks_p,ks_holm_p,ad_statistic,ad_p,ad_holm_p (every digit), so that each number of the
// structural_bias table can be checked against another implementation. None without an f0 problem.
std::optional<std::string> uniformity_tests_csv(const StudyIndex& index, double alpha);

} // namespace mhb
