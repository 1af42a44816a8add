// The "did you mean" of every lookup by name: which names count as near, and the messages.
#include <gtest/gtest.h>

#include "problems/core/did_you_mean.hpp"

namespace mhb {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
    EXPECT_EQ(edit_distance("", ""), 0U);
    EXPECT_EQ(edit_distance("itlbo", "itlbo"), 0U);
    EXPECT_EQ(edit_distance("itlb", "itlbo"), 1U);   // insertion
    EXPECT_EQ(edit_distance("itlboo", "itlbo"), 1U); // deletion
    EXPECT_EQ(edit_distance("itlbe", "itlbo"), 1U);  // substitution
    EXPECT_EQ(edit_distance("iltbo", "itlbo"), 1U);  // swap of neighbours
    EXPECT_EQ(edit_distance("ITLBO", "itlbo"), 0U);  // case aside
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3U);
    EXPECT_EQ(edit_distance("ca", "abc"), 3U); // optimal string alignment: no edit of a swapped pair
    EXPECT_EQ(edit_distance("abc", ""), 3U);
}

TEST(ClosestNames, OffersWhatATypoMeantAndNothingForAStranger) {
    const std::vector<std::string> names = {"itlbo", "tlbo", "pso", "lshade", "lshade-cnepsin", "de"};
    EXPECT_EQ(closest_names("itlb", names), std::vector<std::string>{"itlbo"});
    EXPECT_EQ(closest_names("xtlbo", names), (std::vector<std::string>{"itlbo", "tlbo"})); // a tie: both
    EXPECT_EQ(closest_names("PSO", names), std::vector<std::string>{"pso"});
    EXPECT_EQ(closest_names("lshdae", names), std::vector<std::string>{"lshade"});
    EXPECT_EQ(closest_names("lshade-cn", names), std::vector<std::string>{"lshade-cnepsin"});
    EXPECT_TRUE(closest_names("nope", names).empty());
    EXPECT_TRUE(closest_names("x", {"r", "p"}).empty()); // nothing of a one-letter name survives
    EXPECT_TRUE(closest_names("lsh", names).empty());    // the beginning of two names: neither
}

TEST(DidYouMean, ReadsAsASentence) {
    EXPECT_EQ(did_you_mean({}), "");
    EXPECT_EQ(did_you_mean({"a"}), "did you mean 'a'?");
    EXPECT_EQ(did_you_mean({"a", "b"}), "did you mean 'a' or 'b'?");
    EXPECT_EQ(did_you_mean({"a", "b", "c"}), "did you mean 'a', 'b' or 'c'?");
    EXPECT_EQ(suggestion_or_known("itlbe", {"itlbo", "pso"}), "; did you mean 'itlbo'?");
    EXPECT_EQ(suggestion_or_known("zzz", {"itlbo", "pso"}), "; known: itlbo, pso");
    EXPECT_EQ(suggestion_or_known("zzz", {}), "; known: none");
}

} // namespace
} // namespace mhb
