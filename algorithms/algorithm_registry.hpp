// The registry of optimisers and the built-in registrations.
#pragma once

#include "algorithms/optimizer.hpp"
#include "problems/core/registry.hpp"

namespace mhb {

using AlgorithmRegistry = Registry<Optimizer>;

// Registers every optimiser that ships with mhbench.
void register_builtin_algorithms(AlgorithmRegistry& registry);

// A registry with the built-in optimisers, made once and shared read-only.
const AlgorithmRegistry& builtin_algorithms();

} // namespace mhb
