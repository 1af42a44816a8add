// Every optimiser that evaluates populations as batches (Objective::evaluate_batch) gives the same
// run, bit for bit, whether the problem asks for parallel evaluation or not, and with one thread or
// two: the same best f and x, iteration trace (with best x) and checkpoint trace. The budgets end
// in the middle of a batch, and the target inside one. That these are also the runs the optimisers
// made before they batched is pinned by the golden values of the other tests.
#include <cctype>
#include <gtest/gtest.h>
#include <memory>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/task_arena.h>
#include <string>
#include <vector>

#include "paper_algorithms_support.hpp"

namespace mhb::test {
namespace {

// A problem as it is, apart from what parallel_evaluation() says.
class ParallelAs final : public Problem {
public:
    ParallelAs(const Problem& inner, bool parallel) : inner_(inner), parallel_(parallel) {}
    std::string name() const override { return inner_.name(); }
    Eigen::Index dimension() const override { return inner_.dimension(); }
    const Box& bounds() const override { return inner_.bounds(); }
    double evaluate(const Eigen::VectorXd& x) const override { return inner_.evaluate(x); }
    std::optional<KnownOptimum> known_optimum() const override { return inner_.known_optimum(); }
    bool parallel_evaluation() const override { return parallel_; }

private:
    const Problem& inner_;
    bool parallel_;
};

Outcome run_with_threads(const std::string& spec, const Problem& problem, std::uint64_t seed, Budget budget,
                         int threads) {
    const tbb::global_control cap(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(threads));
    tbb::task_arena arena(threads);
    Outcome out;
    arena.execute([&] { out = run(spec, problem, seed, budget); });
    return out;
}

// The optimisers that batch, with the settings that change which of their loops batch.
const std::vector<std::string>& batching_specs() {
    static const std::vector<std::string> specs = {
        "random-search",
        "random-search:batch=7",
        "de:np=12",
        "lshade",
        "jso",
        "jso:r_ninit=3,H=2",
        "lshade-cnepsin",
        "lshade-cnepsin:pc=1,r_ninit=3,LP=2",
        "nl-shade-lbc",
        "nl-shade-lbc:r_ninit=3,r_h=1",
        "jaya:np=13",
        "pso",
        "pso:np=9,r=learner,vmax=0.2",
        "spso2011:S=11",
        "cmaes",
        "cmaes:restarts=none,lambda=9",
        "cmaes:restarts=bipop",
        "tlbo:np=10",
        "itlbo:np=10",
        "itlbo:np=10,p=0.5,obl_greedy=on,obl_bounds=population",
        "itlbo:np=8,stepwise=off,p=0.3,r=learner",
        "etlbo:np=12,elite=2",
    };
    return specs;
}

class BatchEquivalence : public ::testing::TestWithParam<std::string> {};

TEST_P(BatchEquivalence, SameRunWithOrWithoutParallelEvaluationOnOneOrTwoThreads) {
    const auto rastrigin = builtin_problems().create("rastrigin:dim=4");
    const ParallelAs sequential(*rastrigin, false);
    const ParallelAs parallel(*rastrigin, true);
    // 1999 evaluations end inside a batch for every population size above; 40 iterations end
    // between batches; a target that several runs reach stops one in the middle of a batch.
    for (const Budget budget : {evaluations(1999), iterations(40), Budget{3000, std::nullopt, 1.0}}) {
        for (const std::uint64_t seed : {3u, 11u}) {
            const Outcome reference = run(GetParam(), sequential, seed, budget);
            EXPECT_GT(reference.evaluations, 0);
            for (const int threads : {1, 2}) {
                SCOPED_TRACE("seed " + std::to_string(seed) + ", threads " + std::to_string(threads));
                EXPECT_TRUE(
                    identical(reference, run_with_threads(GetParam(), parallel, seed, budget, threads)));
                EXPECT_TRUE(
                    identical(reference, run_with_threads(GetParam(), sequential, seed, budget, threads)));
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Optimizers, BatchEquivalence, ::testing::ValuesIn(batching_specs()),
                         [](const ::testing::TestParamInfo<std::string>& spec) {
                             std::string name;
                             for (const char ch : spec.param)
                                 name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                             return name + "_" + std::to_string(spec.index);
                         });

} // namespace
} // namespace mhb::test
