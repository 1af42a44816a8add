// The random streams: fixed reference values (they must never change, or every published
// study would change with them) and basic statistical properties.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <vector>

#include "problems/core/rng.hpp"

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

// Rng::jump() is the reference jump of xoshiro256** (2^128 steps). The expected outputs come from
// tests/unit/problems/rng_jump_reference.py, an independent Python coding that seeds as Rng does,
// applies the published JUMP polynomial and checks that it equals T^(2^128), T being the 256x256
// GF(2) matrix of one step (128 squarings, no constants involved).
TEST(Rng, JumpMatchesTheReferenceValues) {
    const struct {
        std::uint64_t seed;
        std::uint64_t once[4];
        std::uint64_t twice[4];
    } cases[] = {
        {42,
         {0x50086ef83cbf4f4aULL, 0xba285ec21347d703ULL, 0x5ea1247b4dc6452aULL, 0x03a5c66424702131ULL},
         {0x8677623ee7544e81ULL, 0x1f591f213a3cb979ULL, 0xbee76be78f4bfe6dULL, 0xf0116185df3b8812ULL}},
        {2024,
         {0xdb417f51b719119cULL, 0xed9e2e1c931c9a18ULL, 0xcb7a29191f04638fULL, 0x9f5201258a50d07aULL},
         {0x66629d0374f45580ULL, 0x37eb14baa04b9a0aULL, 0xf5406743d85b8f03ULL, 0x861b690545a04137ULL}},
    };
    for (const auto& c : cases) {
        Rng once(c.seed);
        once.jump();
        Rng twice = Rng(c.seed).jumped().jumped();
        for (int n = 0; n < 4; ++n) {
            EXPECT_EQ(once.next(), c.once[n]) << "seed " << c.seed << ", output " << n;
            EXPECT_EQ(twice.next(), c.twice[n]) << "seed " << c.seed << ", output " << n;
        }
    }
}

// jumped() takes a copy: the original stream goes on exactly as if nothing had happened.
TEST(Rng, JumpedCopyLeavesTheOriginalUntouched) {
    Rng original(7);
    Rng untouched(7);
    static_cast<void>(original.next());
    static_cast<void>(untouched.next());
    const Rng sub = original.jumped();
    for (int i = 0; i < 100; ++i)
        ASSERT_EQ(original.next(), untouched.next());
    Rng a = sub;
    Rng b = Rng(7).jumped();
    EXPECT_NE(a.next(), b.next()) << "a jump from another position gives another stream";
}

// One jump, two jumps and no jump give three different streams that share no early output.
TEST(Rng, OneJumpTwoJumpsAndNoJumpDiffer) {
    Rng none(11);
    Rng one = Rng(11).jumped();
    Rng two = one.jumped();
    std::vector<std::uint64_t> seen;
    for (int i = 0; i < 1000; ++i)
        for (Rng* r : {&none, &one, &two})
            seen.push_back(r->next());
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(std::adjacent_find(seen.begin(), seen.end()), seen.end());
}

// A cached spare normal belongs to the position it was drawn at: a jumped copy must not return it.
TEST(Rng, JumpDropsTheSpareNormal) {
    Rng with_spare(3);
    static_cast<void>(with_spare.normal()); // caches the second value of the pair
    Rng without_spare = with_spare;
    const double spare = without_spare.normal(); // same state, spare used up
    const double a = with_spare.jumped().normal();
    const double b = without_spare.jumped().normal();
    EXPECT_EQ(a, b);
    EXPECT_NE(a, spare);
}

} // namespace
} // namespace mhb
