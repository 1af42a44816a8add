// Descriptive statistics and COCO's ERT against values computed independently.
#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

#include "results/analysis/statistics.hpp"

namespace mhb {
namespace {

TEST(Statistics, SummaryMatchesNumpyType7Quantiles) {
    // Reference: numpy 1.24 np.percentile([3,1,4,1,5,9,2,6], [25,50,75]) = 1.75, 3.5, 5.25 (linear,
    // = R's type 7) and np.std(ddof=1) = 2.748376143938713; mean 31/8 by hand.
    const Summary s = summarize({3, 1, 4, 1, 5, 9, 2, 6});
    EXPECT_EQ(s.n, 8u);
    EXPECT_DOUBLE_EQ(s.mean, 31.0 / 8.0);
    EXPECT_NEAR(s.std, 2.748376143938713, 1e-14);
    EXPECT_DOUBLE_EQ(s.q25, 1.75);
    EXPECT_DOUBLE_EQ(s.median, 3.5);
    EXPECT_DOUBLE_EQ(s.q75, 5.25);
    EXPECT_DOUBLE_EQ(s.iqr(), 3.5);
    EXPECT_EQ(s.best, 1.0);
    EXPECT_EQ(s.worst, 9.0);
}

TEST(Statistics, StandardDeviationKeepsPrecisionUnderLargeOffsets) {
    // {1e9 + 4, 1e9 + 7, 1e9 + 13, 1e9 + 16}: deviations -6, -3, 3, 6, so the sample variance is
    // 90 / 3 = 30 exactly (by hand); a naive sum of squares loses it at this offset.
    EXPECT_NEAR(standard_deviation({1e9 + 4, 1e9 + 7, 1e9 + 13, 1e9 + 16}), std::sqrt(30.0), 1e-9);
    EXPECT_EQ(standard_deviation({5.0}), 0.0);
    EXPECT_THROW((void)summarize({}), std::invalid_argument);
}

TEST(Statistics, ExpectedRunningTimeAsCocoDefinesIt) {
    // Two successes after 100 and 300 evaluations, one failure that spent 1000: ERT = (100 + 300 +
    // 1000) / 2 = 700 (COCO: sum of evaluations over all runs / number of successes).
    const auto ert = expected_running_time({{true, 100}, {false, 1000}, {true, 300}});
    ASSERT_TRUE(ert.has_value());
    EXPECT_DOUBLE_EQ(*ert, 700.0);
    EXPECT_FALSE(expected_running_time({{false, 10}, {false, 20}}).has_value());
}

} // namespace
} // namespace mhb
