// The parallel multi-start of `mhbench identify --flux-map` is fit_multistart, bit for bit, at any
// thread count: the same starts in the same order, the first best chosen.
#include <gtest/gtest.h>

#include "problems/fluxmap/current_map_fit.hpp"
#include "problems/fluxmap/synthetic_map.hpp"
#include "problems/problem_registry.hpp"
#include "runner/single_problem/flux_map_search.hpp"

namespace mhb {
namespace {

TEST(FluxMapSearch, IsTheSerialMultiStartAtAnyThreadCount) {
    using namespace fluxmap;
    const CurrentMap map(Model::syrm, synthetic_map(Model::syrm, published_values().head(9), 0.05, 3));
    const Box box = builtin_problems().create("fluxmap:model=syrm")->bounds();
    FitOptions options;
    options.starts = 6;
    options.seed = 11;
    options.max_iterations = 60;
    const FitResult serial = fit_multistart(map, box, options);
    for (const int threads : {1, 2, 3}) {
        const FluxMapSearch parallel = search_flux_map(map, box, options, threads);
        EXPECT_EQ(parallel.best.f, serial.f) << threads << " threads";
        EXPECT_EQ(parallel.best.theta, serial.theta) << threads << " threads";
        EXPECT_EQ(parallel.best.start_f, serial.start_f) << threads << " threads";
        ASSERT_EQ(parallel.start_theta.size(), 6u);
    }
}

} // namespace
} // namespace mhb
