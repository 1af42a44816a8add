// The registry of problem families and the built-in registrations.
#pragma once

#include "problems/core/registry.hpp"
#include "problems/problem.hpp"

namespace mhb {

using ProblemRegistry = Registry<Problem>;

// Registers every problem family that ships with mhbench (test functions, PMSM identification).
void register_builtin_problems(ProblemRegistry& registry);

// A registry with the built-in problems, made once and shared read-only.
const ProblemRegistry& builtin_problems();

} // namespace mhb
