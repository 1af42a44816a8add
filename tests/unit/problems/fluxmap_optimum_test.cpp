// Re-derives the best-known optimum shipped for the Baldor flux map (problems/fluxmap/data/
// baldor-optimum.csv) by the documented method: fit_multistart, 100 starts, seed 1, default box.
// Slow (a few seconds per model); it prints the rows of the file and how many starts reached f*.
#include <cstdio>
#include <gtest/gtest.h>

#include "problems/fluxmap/baldor_optimum.hpp"
#include "problems/fluxmap/current_map_fit.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

void rederive_flux_optimum(fluxmap::Model model, const char* spec, const char* name) {
    const auto problem = builtin_problems().create(spec);
    const fluxmap::CurrentMap map(model, fluxmap::baldor_flux_map());
    const fluxmap::FitResult fit = fluxmap::fit_multistart(map, problem->bounds(), fluxmap::FitOptions{});
    std::printf("%s,%.17g", name, fit.f);
    for (Eigen::Index j = 0; j < fit.theta.size(); ++j)
        std::printf(",%.17g", fit.theta[j]);
    std::printf("\n%s: %d of %zu starts within 1e-9 relative of the best\n", name, fit.reached(1e-9),
                fit.start_f.size());
    const double shipped = fluxmap::baldor_optimum(model).f;
    EXPECT_NEAR(fit.f, shipped, 1e-9 * shipped) << name;
    EXPECT_GE(fit.reached(1e-9), 10) << name;
}

TEST(SlowFluxMapOptimum, ReDerivesTheShippedSyrmOptimum) {
    rederive_flux_optimum(fluxmap::Model::syrm, "fluxmap:model=syrm", "syrm");
}

TEST(SlowFluxMapOptimum, ReDerivesTheShippedPmsyrmOptimum) {
    rederive_flux_optimum(fluxmap::Model::pmsyrm, "fluxmap", "pmsyrm");
}

} // namespace
} // namespace mhb
