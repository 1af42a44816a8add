// One run of the (mu/mu_w, lambda)-CMA-ES from a random mean until a stop criterion, a generation
// cap or the budget ends it: its constants, its state and its steps, each a member function. The
// restart strategies (IPOP, BIPOP) and the registry entry are in cmaes.cpp, which documents the
// algorithm and its references.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cstdint>
#include <deque>
#include <limits>
#include <vector>

#include "problems/core/rng.hpp"
#include "problems/objective.hpp"

namespace mhb::cma {

constexpr long long no_generation_cap = std::numeric_limits<long long>::max();

// What one run starts from: its population size, its initial step size (a fraction of the box
// width) and the most generations it may take (BIPOP caps its small-population runs).
struct RunSettings {
    int lambda;
    double sigma0;
    long long max_generations = no_generation_cap;
};

// Runs one CMA-ES run on `objective`. `first` is true until some run has evaluated its first
// generation (which is the Objective's initialisation; later generations are its iterations).
// `tol_x_sigma0` is the step size TolX is relative to (the configured sigma0, the same for every
// restart).
void run_once(Objective& objective, Rng& rng, const RunSettings& settings, double tol_x_sigma0, bool& first);

} // namespace mhb::cma
