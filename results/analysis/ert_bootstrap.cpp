#include "results/analysis/ert_bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mhb {

std::vector<double> simulated_run_lengths(const std::vector<TargetHit>& runs, std::size_t samples, Rng& rng) {
    const bool any_success =
        std::any_of(runs.begin(), runs.end(), [](const TargetHit& h) { return h.success; });
    if (!any_success)
        return {};
    std::vector<double> lengths;
    lengths.reserve(samples);
    for (std::size_t s = 0; s < samples; ++s) {
        double length = 0.0;
        for (;;) {
            const TargetHit& drawn = runs[rng.below(runs.size())];
            length += static_cast<double>(drawn.evaluations);
            if (drawn.success)
                break;
        }
        lengths.push_back(length);
    }
    std::sort(lengths.begin(), lengths.end());
    return lengths;
}

double coco_percentile(const std::vector<double>& sorted, double p) {
    const double n = static_cast<double>(sorted.size());
    const double i = p / 100.0 * n - 0.5;
    if (i <= 0.0)
        return sorted.front();
    if (i >= n - 1.0)
        return sorted.back();
    const auto low = static_cast<std::size_t>(std::floor(i));
    const auto high = static_cast<std::size_t>(std::ceil(i));
    if (low == high)
        return sorted[low];
    return (static_cast<double>(high) - i) * sorted[low] + (i - static_cast<double>(low)) * sorted[high];
}

std::optional<ErtInterval> ert_interval(const std::vector<TargetHit>& runs, Rng& rng, std::size_t samples) {
    if (samples == 0)
        throw std::invalid_argument("ert_interval: needs at least one bootstrap sample");
    const std::optional<double> ert = expected_running_time(runs);
    if (!ert)
        return std::nullopt;
    const std::vector<double> lengths = simulated_run_lengths(runs, samples, rng);
    return ErtInterval{*ert, coco_percentile(lengths, 10.0), coco_percentile(lengths, 90.0)};
}

} // namespace mhb
