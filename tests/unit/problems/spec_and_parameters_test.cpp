// Specs (`name:key=value,...`), typed parameter validation and the registry's errors.
#include <gtest/gtest.h>

#include "problems/core/spec.hpp"
#include "problems/core/spec_grid.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

TEST(Spec, ParsesNameAndParametersKeepingColonsInValues) {
    const Spec s = Spec::parse("pmsm:data=drive.csv,rs=0:1");
    EXPECT_EQ(s.name, "pmsm");
    ASSERT_EQ(s.parameters.size(), 2u);
    EXPECT_EQ(*s.find("rs"), "0:1");
    EXPECT_EQ(s.canonical(), "pmsm:data=drive.csv,rs=0:1");
    EXPECT_EQ(Spec::parse("itlbo:tutorial=off,obl=off").canonical(), "itlbo:obl=off,tutorial=off");
    EXPECT_EQ(Spec::parse("tlbo").canonical(), "tlbo");
}

TEST(Spec, RejectsMalformedText) {
    EXPECT_THROW(Spec::parse(""), std::invalid_argument);
    EXPECT_THROW(Spec::parse(":w=1"), std::invalid_argument);
    EXPECT_THROW(Spec::parse("pso:w"), std::invalid_argument);
    EXPECT_THROW(Spec::parse("pso:w="), std::invalid_argument);
    EXPECT_THROW(Spec::parse("pso:w=1,w=2"), std::invalid_argument);
    EXPECT_THROW(Spec::parse("p$o"), std::invalid_argument);
}

TEST(Spec, SplitsListsOnWhitespace) {
    EXPECT_EQ(split_spec_list("  itlbo  tlbo\tpso:w=0.7 "),
              (std::vector<std::string>{"itlbo", "tlbo", "pso:w=0.7"}));
}

TEST(Parameters, ValidatesTypesAndRangesAndReportsEveryError) {
    const std::vector<ParameterInfo> declared = {
        ParameterInfo::real("w", 0.5, 0.0, 1.0, "inertia"),
        ParameterInfo::integer("np", 50, 2, 10000, "population"),
        ParameterInfo::boolean("obl", true, "mutation"),
        ParameterInfo::choice("mode", "a", {"a", "b"}, "mode"),
    };
    const auto values = validate_parameters("x", declared, Spec::parse("x:w=0.25,obl=off"));
    EXPECT_DOUBLE_EQ(values.real("w"), 0.25);
    EXPECT_EQ(values.integer("np"), 50);
    EXPECT_FALSE(values.boolean("obl"));
    EXPECT_EQ(values.text("mode"), "a");
    EXPECT_TRUE(values.given("w"));
    EXPECT_FALSE(values.given("np"));
    try {
        validate_parameters("pso", declared, Spec::parse("pso:w=1.3,np=1.5,obl=maybe,mode=c,zz=1"));
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("pso: parameter 'w' = 1.3 is outside [0, 1]"), std::string::npos) << m;
        EXPECT_NE(m.find("'np' = 1.5 is not an integer"), std::string::npos) << m;
        EXPECT_NE(m.find("'obl' = maybe"), std::string::npos) << m;
        EXPECT_NE(m.find("'mode' = c is not one of {a, b}"), std::string::npos) << m;
        EXPECT_NE(m.find("unknown parameter 'zz'; known: w, np, obl, mode"), std::string::npos) << m;
    }
    EXPECT_THROW(validate_parameters("x", declared, Spec::parse("x:w=nan")), std::invalid_argument);
}

TEST(Registry, UnknownNamesListWhatIsKnown) {
    try {
        (void)builtin_problems().create("no_such_problem");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("unknown problem 'no_such_problem'; known: "),
                  std::string::npos);
        EXPECT_NE(std::string(e.what()).find("sphere"), std::string::npos);
    }
}

TEST(Registry, ExpandsRangesOfRangedIntegers) {
    ProblemRegistry r("problem");
    r.add({"toy",
           1,
           "",
           "",
           {ParameterInfo::integer("f", 1, 1, 24, "function").ranged(),
            ParameterInfo::integer("dim", 2, 1, 40, "dimension")},
           nullptr});
    const auto specs = r.expand(Spec::parse("toy:f=3-5,dim=10"));
    ASSERT_EQ(specs.size(), 3u);
    EXPECT_EQ(specs[0].canonical(), "toy:dim=10,f=3");
    EXPECT_EQ(specs[2].canonical(), "toy:dim=10,f=5");
    EXPECT_EQ(r.expand(Spec::parse("toy:f=-1")).size(), 1u); // a negative number is not a range
    EXPECT_THROW((void)r.expand(Spec::parse("toy:f=5-3")), std::invalid_argument);
}

// Found by tests/fuzz/fuzz_spec: the width of a range overflowed long long (so a range of 2^64
// values passed the length check) and a range ending at the largest long long never ended.
TEST(Registry, RangesAtTheEndsOfLongLongNeitherOverflowNorLoop) {
    ProblemRegistry r("problem");
    r.add({"toy", 1, "", "", {ParameterInfo::integer("f", 1, 1, 24, "function").ranged()}, nullptr});
    EXPECT_THROW((void)r.expand(Spec::parse("toy:f=-9223372036854775807-9223372036854775807")),
                 std::invalid_argument);
    const auto top = r.expand(Spec::parse("toy:f=9223372036854775805-9223372036854775807"));
    ASSERT_EQ(top.size(), 3u);
    EXPECT_EQ(top[2].canonical(), "toy:f=9223372036854775807");
}

} // namespace
} // namespace mhb
