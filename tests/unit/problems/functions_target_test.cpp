// Known optima make target-based stopping work on every test function: a run that reaches
// f - f* <= target stops and records the evaluations it took. Also the centre-bias study's list.
#include <gtest/gtest.h>

#include "problems/functions/classic_function.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

void expect_target_reached_at_the_optimum(const std::string& spec) {
    const auto p = builtin_problems().create(spec);
    Objective objective(*p, Budget{100, std::nullopt, 1e-8});
    Eigen::VectorXd far = p->bounds().upper;
    Eigen::VectorXd at_optimum = *p->known_optimum()->x;
    objective.evaluate(far);
    objective.evaluate(far);
    EXPECT_FALSE(objective.exhausted()) << spec;
    objective.evaluate(at_optimum);
    EXPECT_TRUE(objective.exhausted()) << spec;
    ASSERT_TRUE(objective.evaluations_to_target().has_value()) << spec;
    EXPECT_EQ(*objective.evaluations_to_target(), 3) << spec;
}

TEST(FunctionTargets, RunsStopOnReachingTheTargetOfEveryFunction) {
    for (const auto& name : classic_function_names()) {
        if (name == "quartic")
            continue; // its noise U[0, 1) keeps f - f* above any small target, by design
        expect_target_reached_at_the_optimum(name + ":dim=10,shift=1,rotate=1,instance=2");
    }
    for (int f = 1; f <= 24; ++f)
        expect_target_reached_at_the_optimum("bbob:f=" + std::to_string(f) + ",dim=10,instance=3");
}

TEST(FunctionTargets, CentreBiasStudyPairsEveryClassicFunctionWithItsShiftedVariant) {
    const auto specs = centre_bias_problem_specs(30);
    ASSERT_EQ(specs.size(), 2 * classic_function_names().size());
    EXPECT_EQ(specs[0], "sphere:dim=30");
    EXPECT_EQ(specs[1], "sphere:dim=30,instance=1,shift=on");
    for (std::size_t i = 0; i < specs.size(); i += 2) {
        const auto plain = builtin_problems().create(specs[i]);
        const auto shifted = builtin_problems().create(specs[i + 1]);
        EXPECT_EQ(plain->known_optimum()->f, shifted->known_optimum()->f) << specs[i];
        EXPECT_NE(*plain->known_optimum()->x, *shifted->known_optimum()->x) << specs[i];
    }
}

} // namespace
} // namespace mhb
