// Grids: braces expand to one spec per combination, in a fixed order, and every malformed grid
// is an error naming the spec; registries recognise specs that mean the same component.
#include <gtest/gtest.h>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/spec.hpp"
#include "problems/core/spec_grid.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

std::vector<std::string> texts(const std::vector<GridVariant>& variants) {
    std::vector<std::string> out;
    for (const auto& v : variants)
        out.push_back(v.text);
    return out;
}

std::string grid_error(std::string_view text) {
    try {
        (void)expand_grid(text);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "no error";
}

TEST(SpecGrid, ExpandsEveryCombinationFirstKeySlowest) {
    const auto v = expand_grid("itlbo:tutorial={on,off},stepwise={on,off},obl={on,off}");
    ASSERT_EQ(v.size(), 8u);
    EXPECT_EQ(v.front().text, "itlbo:tutorial=on,stepwise=on,obl=on");
    EXPECT_EQ(v[1].text, "itlbo:tutorial=on,stepwise=on,obl=off");
    EXPECT_EQ(v.back().text, "itlbo:tutorial=off,stepwise=off,obl=off");
    EXPECT_EQ(v[5].varying, (std::vector<std::pair<std::string, std::string>>{
                                {"tutorial", "off"}, {"stepwise", "on"}, {"obl", "off"}}));
    EXPECT_EQ(texts(expand_grid("pso:w={0.4, 0.5 ,0.7},c1=2")),
              (std::vector<std::string>{"pso:w=0.4,c1=2", "pso:w=0.5,c1=2", "pso:w=0.7,c1=2"}));
    // Fixed keys stay where they are; ranges inside a set are left to the registry.
    EXPECT_EQ(
        texts(expand_grid("bbob:f=1-24,dim={2,5},instance=1-15")),
        (std::vector<std::string>{"bbob:f=1-24,dim=2,instance=1-15", "bbob:f=1-24,dim=5,instance=1-15"}));
    EXPECT_EQ(texts(expand_grid("sphere:dim={1-2,7}")),
              (std::vector<std::string>{"sphere:dim=1-2", "sphere:dim=7"}));
    // No braces: the spec itself, nothing varying.
    const auto one = expand_grid("  tlbo:np=30 ");
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].text, "tlbo:np=30");
    EXPECT_TRUE(one[0].varying.empty());
    EXPECT_EQ(expand_grid("de:F={0.5}")[0].varying.size(), 1u); // a set of one still varies
}

TEST(SpecGrid, RefusesNestedEmptyDuplicateAndUnbalancedSets) {
    EXPECT_EQ(grid_error("pso:w={0.4,{0.5}}"),
              "'pso:w={0.4,{0.5}}': nested braces are not allowed (a grid lists plain values: key={a,b,c})");
    EXPECT_EQ(grid_error("pso:w={}"), "'pso:w={}': parameter 'w': the set {} is empty");
    EXPECT_EQ(grid_error("pso:w={0.4,,0.5}"),
              "'pso:w={0.4,,0.5}': parameter 'w': the set has an empty value");
    EXPECT_EQ(grid_error("pso:w={0.4,0.4}"),
              "'pso:w={0.4,0.4}': parameter 'w': value '0.4' is listed twice in the set");
    EXPECT_EQ(grid_error("pso:w={0.4"), "'pso:w={0.4': a '{' is not closed");
    EXPECT_EQ(grid_error("pso:w=0.4}"), "'pso:w=0.4}': a '}' has no matching '{'");
    EXPECT_EQ(grid_error("{pso,de}"), "'{pso,de}': braces belong in a parameter's value (name:key={a,b})");
    EXPECT_EQ(grid_error("pso:w=0.{4,5}"),
              "'pso:w=0.{4,5}': parameter 'w': a set is written {a,b,...} and nothing else");
}

// Found by tests/fuzz/fuzz_spec: 30 two-valued sets in 300 bytes asked for 2^30 variants and ran
// out of memory; a grid's size is now checked before it is expanded.
TEST(SpecGrid, RefusesGridsOfTooManyVariantsBeforeExpanding) {
    std::string text = "pso:";
    for (int i = 0; i < 30; ++i) {
        // Appended piece by piece: `(...) + std::string("k") + ...` makes GCC 12 warn falsely
        // (-Wstringop-overflow) once inlined into a unity batch.
        if (i > 0)
            text += ',';
        text += 'k';
        text += std::to_string(i);
        text += "={0,1}";
    }
    try {
        (void)expand_grid(text);
        FAIL() << "a grid of 2^30 variants was expanded";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("more than 100000 variants"), std::string::npos) << e.what();
    }
    EXPECT_EQ(expand_grid("pso:a={1,2,3,4,5,6,7,8,9,10},b={1,2,3,4,5,6,7,8,9,10},c={1,2,3,4,5,6,7,8,9,10},"
                          "d={1,2,3,4,5,6,7,8,9,10},e={1,2,3,4,5,6,7,8,9,10}")
                  .size(),
              max_grid_variants); // exactly the limit is allowed
}

TEST(SpecGrid, SpecListsKeepBracedSpacesTogether) {
    EXPECT_EQ(split_spec_list("  itlbo  tlbo\tpso:w={0.4, 0.5} de\n"),
              (std::vector<std::string>{"itlbo", "tlbo", "pso:w={0.4,0.5}", "de"}));
}

TEST(SpecIdentity, SpecsThatMeanTheSameOptimiserHaveOneCanonicalForm) {
    const auto& r = builtin_algorithms();
    const auto minimal = [&](const char* text) { return r.minimal(Spec::parse(text)).canonical(); };
    EXPECT_EQ(minimal("tlbo"), "tlbo");
    EXPECT_EQ(minimal("tlbo:np=50"), "tlbo");
    EXPECT_EQ(minimal("tlbo:np=5e1"), "tlbo");
    EXPECT_EQ(minimal("itlbo:obl=false,tutorial=on,p=0.10"), "itlbo:obl=off");
    EXPECT_EQ(minimal("pso:w=0.70,c1=2.0"), "pso:w=0.7");
    EXPECT_NE(minimal("tlbo:np=30"), minimal("tlbo"));
    // The full form lists every parameter with its value, defaults included.
    EXPECT_EQ(r.full(Spec::parse("tlbo:np=30")).canonical().rfind("tlbo:np=30", 0), 0u);
    EXPECT_NE(r.full(Spec::parse("itlbo")).canonical().find("tutorial=on"), std::string::npos);
    // Problems keep the keys written (reports read them) with values in normal form.
    EXPECT_EQ(builtin_problems().normalised(Spec::parse("sphere:dim=1e1,bound=5.0")).canonical(),
              "sphere:bound=5,dim=10");
    EXPECT_THROW((void)r.minimal(Spec::parse("tlbo:np=1")), std::invalid_argument);
}

} // namespace
} // namespace mhb
