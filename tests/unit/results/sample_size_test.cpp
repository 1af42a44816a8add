// Sample sizes before a study (results/analysis/sample_size.hpp) against R's power.t.test and
// CAISEr's calc_instances.
#include <gtest/gtest.h>
#include <stdexcept>

#include "results/analysis/sample_size.hpp"

namespace mhb {
namespace sample_size_test {

TEST(SampleSize, PairedTPowerIsRsPowerTTest) {
    // power.t.test(n = 34, delta = 0.5, sd = 1, sig.level = 0.05, type = "paired")$power = 0.8077775
    EXPECT_NEAR(paired_t_power(34, 0.5, 0.05), 0.8077775, 2e-6);
    // power.t.test(n = 10, delta = 1, type = "paired")$power = 0.8030962
    EXPECT_NEAR(paired_t_power(10, 1.0, 0.05), 0.8030962, 2e-6);
    EXPECT_EQ(paired_t_power(1, 1.0, 0.05), 0.0);
}

TEST(SampleSize, InstancesForOneComparisonAreTheTTestsN) {
    // power.t.test(delta = 0.5, power = 0.8, type = "paired")$n = 33.36713 -> 34
    const InstancePlan half = plan_instances(1, 0.5, 0.8, 0.05, PowerTarget::mean, PlannedTest::t_test);
    EXPECT_EQ(half.instances, 34);
    EXPECT_EQ(half.t_test_instances, 34);
    // CAISEr: ceiling(34 / 0.86) = 40 for the Wilcoxon signed-rank test.
    EXPECT_EQ(plan_instances(1, 0.5, 0.8, 0.05, PowerTarget::mean, PlannedTest::wilcoxon).instances, 40);
    // power.t.test(delta = 0.8, power = 0.8, type = "paired")$n = 14.30276 -> 15
    EXPECT_EQ(plan_instances(1, 0.8, 0.8, 0.05, PowerTarget::mean, PlannedTest::t_test).instances, 15);
}

TEST(SampleSize, SeveralComparisonsUseHolmLevels) {
    const InstancePlan mean = plan_instances(3, 0.5, 0.8, 0.05, PowerTarget::mean, PlannedTest::t_test);
    ASSERT_EQ(mean.levels.size(), 3u);
    EXPECT_DOUBLE_EQ(mean.levels[0], 0.05 / 3);
    EXPECT_DOUBLE_EQ(mean.levels[2], 0.05);
    EXPECT_GE(mean.mean_power, 0.8);
    // One problem fewer would not do: the smallest N.
    const InstancePlan worst =
        plan_instances(3, 0.5, 0.8, 0.05, PowerTarget::worst_case, PlannedTest::t_test);
    EXPECT_GE(worst.powers.front(), 0.8);
    EXPECT_LT(paired_t_power(worst.t_test_instances - 1, 0.5, 0.05 / 3), 0.8);
    EXPECT_GT(worst.instances, mean.instances);
    EXPECT_GT(mean.instances, 34);
}

TEST(SampleSize, RunsForAPrecision) {
    EXPECT_EQ(runs_for_precision(0.5, 0.1), 25);
    EXPECT_EQ(runs_for_precision(0.51, 0.1), 27);
    EXPECT_EQ(runs_for_precision(0.0, 0.1), 2);
    EXPECT_THROW(runs_for_precision(1.0, 0.0), std::invalid_argument);
    EXPECT_THROW(plan_instances(1, 0.0, 0.8, 0.05, PowerTarget::mean, PlannedTest::t_test),
                 std::invalid_argument);
    EXPECT_THROW(plan_instances(1, 0.5, 1.0, 0.05, PowerTarget::mean, PlannedTest::t_test),
                 std::invalid_argument);
}

} // namespace sample_size_test
} // namespace mhb
