#include "problems/pmsm/segments.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mhb::pmsm {

double sampling_period(const Dataset& data, const std::string& source) {
    std::vector<double> steps;
    steps.reserve(data.size());
    for (std::size_t k = 0; k + 1 < data.size(); ++k)
        if (data.t[k + 1] > data.t[k])
            steps.push_back(data.t[k + 1] - data.t[k]);
    if (steps.empty())
        throw std::invalid_argument(source +
                                    ": column 't' never increases, so the sampling period is unknown");
    const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), middle, steps.end());
    return *middle;
}

bool consecutive(const Dataset& data, std::size_t k, double Ts) {
    return std::fabs(data.t[k + 1] - data.t[k] - Ts) <= 0.01 * Ts;
}

std::vector<Segment> contiguous_segments(const Dataset& data, double Ts) {
    std::vector<Segment> out;
    std::size_t begin = 0;
    for (std::size_t k = 0; k < data.size(); ++k)
        if (k + 1 == data.size() || !consecutive(data, k, Ts)) {
            out.push_back({begin, k + 1});
            begin = k + 1;
        }
    return out;
}

} // namespace mhb::pmsm
