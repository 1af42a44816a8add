// The random streams: fixed reference values (they must never change, or every published
// study would change with them) and basic statistical properties.
#include <cmath>
#include <gtest/gtest.h>

#include "problems/rng.hpp"

namespace mhb {
namespace {

TEST(Rng, StableHashIsFnv1a) {
    // FNV-1a 64 reference values (Fowler, Noll, Vo).
    EXPECT_EQ(stable_hash(""), 0xcbf29ce484222325ULL);
    EXPECT_EQ(stable_hash("a"), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(stable_hash("foobar"), 0x85944171f73967e8ULL);
}

TEST(Rng, SameSeedGivesTheSameStream) {
    // The first output of SplitMix64 from state 0, the published reference value.
    EXPECT_EQ(mix64(0), 0xe220a8397b1dcdafULL);
    Rng a(42);
    Rng b(42);
    for (int i = 0; i < 1000; ++i)
        ASSERT_EQ(a.next(), b.next());
    Rng c(43);
    EXPECT_NE(Rng(42).next(), c.next());
}

TEST(Rng, DerivedSeedsDependOnEveryIngredient) {
    const auto s = derive_seed(1, "itlbo", "pmsm", 0);
    EXPECT_NE(s, derive_seed(2, "itlbo", "pmsm", 0));
    EXPECT_NE(s, derive_seed(1, "tlbo", "pmsm", 0));
    EXPECT_NE(s, derive_seed(1, "itlbo", "sphere", 0));
    EXPECT_NE(s, derive_seed(1, "itlbo", "pmsm", 1));
    EXPECT_NE(derive_seed(1, "ab", "c", 0), derive_seed(1, "a", "bc", 0));
    EXPECT_EQ(s, derive_seed(1, "itlbo", "pmsm", 0));
}

TEST(Rng, UniformBelowAndNormalHaveTheRightMoments) {
    Rng rng(7);
    const int n = 200000;
    double sum = 0, sum2 = 0, nsum = 0, nsum2 = 0;
    std::vector<int> counts(7, 0);
    for (int i = 0; i < n; ++i) {
        const double u = rng.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
        sum2 += u * u;
        ++counts[rng.below(7)];
        const double z = rng.normal();
        nsum += z;
        nsum2 += z * z;
    }
    EXPECT_NEAR(sum / n, 0.5, 0.005);
    EXPECT_NEAR(sum2 / n - 0.25, 1.0 / 12.0, 0.003);
    for (int c : counts)
        EXPECT_NEAR(c / double(n), 1.0 / 7.0, 0.005);
    EXPECT_NEAR(nsum / n, 0.0, 0.01);
    EXPECT_NEAR(nsum2 / n, 1.0, 0.02);
    for (int i = 0; i < 1000; ++i) {
        const auto j = rng.below_except(5, 2);
        ASSERT_NE(j, 2u);
        ASSERT_LT(j, 5u);
    }
}

} // namespace
} // namespace mhb
