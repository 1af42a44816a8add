// The cec2017 preset's algorithms' own time per evaluation (their overhead, the objective excluded)
// at D = 10, 30, 50 and 100, the CEC 2017 dimensions: whole runs with the defaults on the sphere of that
// dimension, with a budget of 2000 x D evaluations, so that population-size reduction and restarts go through
// their whole schedule as in a competition run (cec2017-smoke's budget; the full protocol's 10 000 x D gives
// the same schedule five times slower).
//   baseline/<spec>/<D>   whole runs; the counter per_eval is the run's time per evaluation.
//   objective_only/<D>    the same number of Objective::evaluate calls on stored points: the cost
//                         of the sphere plus the Objective's counting, repair and records.
// An optimiser's overhead per evaluation at D is per_eval(baseline) - per_eval(objective_only).
// Run: build/release/tests/bench/cec_baselines_overhead_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>
#include <string>
#include <vector>

#include "problems/problem_registry.hpp"
#include "tests/bench/overhead_support.hpp"

namespace mhb {
namespace {

constexpr int dimensions[] = {10, 30, 50, 100};

std::int64_t protocol_budget(int dimension) {
    return 2000 * static_cast<std::int64_t>(dimension);
}

const Problem& sphere_of(int dimension) {
    static const auto d10 = builtin_problems().create("sphere:dim=10");
    static const auto d30 = builtin_problems().create("sphere:dim=30");
    static const auto d50 = builtin_problems().create("sphere:dim=50");
    static const auto d100 = builtin_problems().create("sphere:dim=100");
    return dimension == 10 ? *d10 : dimension == 30 ? *d30 : dimension == 50 ? *d50 : *d100;
}

void sphere_objective_only(benchmark::State& state, int dimension) {
    bench::objective_only_runs(state, sphere_of(dimension), protocol_budget(dimension));
}

void baseline_run(benchmark::State& state, const std::string& spec, int dimension) {
    bench::optimizer_runs(state, spec, sphere_of(dimension), protocol_budget(dimension));
}

// The algorithms of the cec2017 preset (scripts/studies/cec2017.ini), in its order.
const std::vector<std::string>& cec_baseline_specs() {
    static const std::vector<std::string> specs = {"itlbo",        "tlbo",  "pso",
                                                   "lshade",       "jso",   "lshade-cnepsin",
                                                   "nl-shade-lbc", "cmaes", "cmaes:restarts=bipop"};
    return specs;
}

const bool registered = [] {
    // Names are built by appending: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
    const auto named = [](std::string prefix, int dimension) {
        prefix += '/';
        prefix += std::to_string(dimension);
        return prefix;
    };
    for (const int dimension : dimensions) {
        benchmark::RegisterBenchmark(named("objective_only", dimension).c_str(), sphere_objective_only,
                                     dimension)
            ->Unit(benchmark::kMillisecond);
        for (const auto& spec : cec_baseline_specs())
            benchmark::RegisterBenchmark(named("baseline/" + spec, dimension).c_str(), baseline_run, spec,
                                         dimension)
                ->Unit(benchmark::kMillisecond);
    }
    return true;
}();

} // namespace
} // namespace mhb
