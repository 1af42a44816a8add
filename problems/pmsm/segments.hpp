// The time structure of a dataset: its sampling period and its contiguous stretches. A logged
// window may jump in t (the shared `_ss` files hold the ends of two plateaus), and a derivative
// or a simulation must never run across such a jump, so every model works segment by segment.
#pragma once

#include <cstddef>
#include <vector>

#include "problems/pmsm/dataset.hpp"

namespace mhb::pmsm {

// Rows [begin, end) whose consecutive times are one sampling period apart.
struct Segment {
    std::size_t begin = 0;
    std::size_t end = 0;
    [[nodiscard]] std::size_t size() const { return end - begin; }
};

// The sampling period: the median of the positive time steps. Throws std::invalid_argument
// (naming `source`) when the dataset has fewer than two rows or no positive step.
double sampling_period(const Dataset& data, const std::string& source);

// Whether rows k and k + 1 are one period apart (within 1 % of Ts).
bool consecutive(const Dataset& data, std::size_t k, double Ts);

// The maximal runs of consecutive rows, in order; a single row is a segment of size 1.
std::vector<Segment> contiguous_segments(const Dataset& data, double Ts);

} // namespace mhb::pmsm
