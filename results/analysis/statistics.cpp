#include "results/analysis/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mhb {

double mean(const std::vector<double>& values) {
    if (values.empty())
        throw std::invalid_argument("mean of an empty sample");
    double sum = 0.0;
    for (double v : values)
        sum += v;
    return sum / static_cast<double>(values.size());
}

double standard_deviation(const std::vector<double>& values) {
    if (values.size() < 2)
        return 0.0;
    // (v - m) would be inf - inf = NaN: the spread of a sample with an infinite value is unbounded.
    if (std::any_of(values.begin(), values.end(), [](double v) { return std::isinf(v); }))
        return std::numeric_limits<double>::infinity();
    const double m = mean(values);
    // Two-pass with the compensating term (sum of deviations), which is exactly zero in exact
    // arithmetic and corrects the rounding of m.
    double squares = 0.0;
    double deviations = 0.0;
    for (double v : values) {
        squares += (v - m) * (v - m);
        deviations += v - m;
    }
    const double n = static_cast<double>(values.size());
    return std::sqrt((squares - deviations * deviations / n) / (n - 1.0));
}

double median_of(std::vector<double> values) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    return quantile_sorted(values, 0.5);
}

double quantile_sorted(const std::vector<double>& sorted, double p) {
    if (sorted.empty())
        throw std::invalid_argument("quantile of an empty sample");
    if (!(p >= 0.0 && p <= 1.0))
        throw std::invalid_argument("quantile probability must be in [0, 1]");
    const double h = (static_cast<double>(sorted.size()) - 1.0) * p;
    const auto lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    const double fraction = h - static_cast<double>(lo);
    // Equal neighbours (two +inf, say) or no fraction: the order statistic itself, since
    // 0 * (inf - inf) would be NaN.
    if (fraction == 0.0 || sorted[hi] == sorted[lo])
        return sorted[lo];
    return sorted[lo] + fraction * (sorted[hi] - sorted[lo]);
}

Summary summarize(const std::vector<double>& values) {
    if (values.empty())
        throw std::invalid_argument("summary of an empty sample");
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    Summary s;
    s.n = values.size();
    s.mean = mean(values);
    s.std = standard_deviation(values);
    s.median = quantile_sorted(sorted, 0.5);
    s.q25 = quantile_sorted(sorted, 0.25);
    s.q75 = quantile_sorted(sorted, 0.75);
    s.best = sorted.front();
    s.worst = sorted.back();
    s.infinite = static_cast<std::size_t>(
        std::count_if(values.begin(), values.end(), [](double v) { return std::isinf(v); }));
    return s;
}

std::vector<double> paired_differences(std::span<const double> x, std::span<const double> y) {
    std::vector<double> d;
    for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i)
        if (!std::isnan(x[i]) && !std::isnan(y[i]))
            d.push_back(x[i] == y[i] ? 0.0 : x[i] - y[i]);
    return d;
}

std::optional<double> expected_running_time(const std::vector<TargetHit>& runs) {
    double evaluations = 0.0;
    std::size_t successes = 0;
    for (const auto& r : runs) {
        evaluations += static_cast<double>(r.evaluations);
        successes += r.success ? 1 : 0;
    }
    if (successes == 0)
        return std::nullopt;
    return evaluations / static_cast<double>(successes);
}

} // namespace mhb
