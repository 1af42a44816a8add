// Descriptive statistics of a sample of final values (per problem x algorithm): mean and std
// (two-pass, so large offsets lose no precision), quantiles as R's default (type 7), and the
// expected running time to a target as COCO defines it.
//
// Infinite values (+inf is a legal final value: the worst) are kept. The mean is then +inf (NaN
// only for a sample holding both +inf and -inf), the standard deviation +inf (the spread is
// unbounded); quantiles, best and worst are order statistics and treat +inf as the largest value,
// as R's quantile() does (a quantile between a finite value and +inf is +inf; between two equal
// infinities it is that infinity, never inf - inf).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace mhb {

struct Summary {
    std::size_t n = 0;
    double mean = 0.0;
    double std = 0.0; // sample standard deviation (n - 1); 0 for n < 2
    double median = 0.0;
    double q25 = 0.0;
    double q75 = 0.0;
    double best = 0.0;        // minimum
    double worst = 0.0;       // maximum
    std::size_t infinite = 0; // values that are +inf or -inf
    // q75 - q25; 0 when both quartiles are the same infinity (a tie, not inf - inf).
    [[nodiscard]] double iqr() const { return q75 == q25 ? 0.0 : q75 - q25; }
};

// Throws std::invalid_argument on an empty sample.
Summary summarize(const std::vector<double>& values);

double mean(const std::vector<double>& values);
// Sample standard deviation by the two-pass formula; 0 for fewer than two values; +inf when a value
// is infinite (and there are at least two values).
double standard_deviation(const std::vector<double>& values);
// Quantile of probability p in [0, 1], linear interpolation between order statistics
// (Hyndman & Fan type 7, R's and NumPy's default). `sorted` must be sorted ascending.
double quantile_sorted(const std::vector<double>& sorted, double p);
// The median (type 7) of an unsorted sample; 0 for an empty one.
double median_of(std::vector<double> values);
// x[i] - y[i] over the pairs of the two samples (the shorter's length), two equal values a zero
// difference (two equal infinities are a tie, not inf - inf = NaN); a pair holding a NaN (a failed
// run) is left out.
std::vector<double> paired_differences(std::span<const double> x, std::span<const double> y);

// One run as the ERT sees it: whether it reached the target and the evaluations it spent
// (to the target if it did, in total otherwise).
struct TargetHit {
    bool success = false;
    std::int64_t evaluations = 0;
};

// COCO's expected running time: the evaluations of all runs (to the target for successful runs,
// all of them for unsuccessful ones) divided by the number of successful runs. Empty when no run
// succeeded (ERT is infinite).
std::optional<double> expected_running_time(const std::vector<TargetHit>& runs);

} // namespace mhb
