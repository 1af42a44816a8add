// Budgets of the optimiser tests.
#pragma once

#include <cstdint>

#include "problems/objective.hpp"

namespace mhb::test_support {

// A budget of n evaluations and nothing else (no iteration limit, no target).
inline Budget evaluations(std::int64_t n) {
    Budget b;
    b.max_evaluations = n;
    return b;
}

} // namespace mhb::test_support
