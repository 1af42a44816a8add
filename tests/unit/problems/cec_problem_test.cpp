// The `cec2017` and `cec2022` problem families through the registry: box, dimension and known
// optimum, range expansion, refusals that name what exists, the availability table against the
// shipped data, and evaluation from several threads at once.
#include <gtest/gtest.h>
#include <stdexcept>
#include <thread>

#include "problems/cec/cec_data.hpp"
#include "problems/cec/cec_function.hpp"
#include "problems/core/spec.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

std::string refusal(const std::string& spec) {
    try {
        (void)builtin_problems().create(spec);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(CecProblem, BoxDimensionAndKnownOptimum) {
    const auto problem = builtin_problems().create("cec2017:f=3,dim=10");
    EXPECT_EQ(problem->name(), "cec2017");
    EXPECT_EQ(problem->dimension(), 10);
    EXPECT_EQ(problem->bounds().lower, Eigen::VectorXd::Constant(10, -100.0));
    EXPECT_EQ(problem->bounds().upper, Eigen::VectorXd::Constant(10, 100.0));
    const auto optimum = problem->known_optimum();
    ASSERT_TRUE(optimum.has_value());
    EXPECT_EQ(optimum->f, 300.0);
    ASSERT_TRUE(optimum->x.has_value());
    // x* is o: the first 10 numbers of shift_data_3.txt.
    const auto shift = cec::data_file(cec::Suite::cec2017, "shift_data_3.txt")->range(0, 10);
    for (Eigen::Index i = 0; i < 10; ++i)
        EXPECT_EQ((*optimum->x)[i], shift[static_cast<std::size_t>(i)]);
    EXPECT_EQ(problem->evaluate(*optimum->x), 300.0);
    EXPECT_TRUE(problem->warnings().empty());

    const auto p2022 = builtin_problems().create("cec2022:f=10,dim=20");
    EXPECT_EQ(p2022->name(), "cec2022");
    EXPECT_EQ(p2022->dimension(), 20);
    EXPECT_EQ(p2022->known_optimum()->f, 2400.0);
    // Composition: x* is o_1, the first 20 numbers of line 1.
    EXPECT_EQ((*p2022->known_optimum()->x)[19],
              cec::data_file(cec::Suite::cec2022, "shift_data_10.txt")->line_prefix(0, 20)[19]);
}

TEST(CecProblem, DefaultsAreDimensionTenAndFunctionOne) {
    const auto problem = builtin_problems().create("cec2022");
    EXPECT_EQ(problem->dimension(), 10);
    EXPECT_EQ(problem->known_optimum()->f, 300.0);
}

TEST(CecProblem, Cec2017FunctionTwoIsDefinedAndFlagged) {
    const auto problem = builtin_problems().create("cec2017:f=2,dim=10");
    EXPECT_EQ(problem->known_optimum()->f, 200.0);
    ASSERT_EQ(problem->warnings().size(), 1u);
    EXPECT_NE(problem->warnings()[0].find("excluded from the competition"), std::string::npos);
    const auto& entry = builtin_problems().find("cec2017");
    EXPECT_NE(entry.parameters[0].help.find("2 Shifted and Rotated Sum of Different Power (dropped from the "
                                            "final CEC 2017 definitions and excluded from the competition"),
              std::string::npos)
        << entry.parameters[0].help;
}

TEST(CecProblem, FunctionRangesExpand) {
    const auto specs = builtin_problems().expand(Spec::parse("cec2017:f=1-30,dim=10"));
    ASSERT_EQ(specs.size(), 30u);
    EXPECT_EQ(specs[29].canonical(), "cec2017:dim=10,f=30");
    EXPECT_EQ(builtin_problems().expand(Spec::parse("cec2022:f=1-12,dim=20")).size(), 12u);
}

TEST(CecProblem, RefusesWhatHasNoDataNamingWhatExists) {
    EXPECT_EQ(refusal("cec2017:f=11,dim=20"),
              "cec2017: parameter 'dim' = 20 has no official data for f=11 (dim = 10, 30, 50, 100 only)");
    EXPECT_EQ(
        refusal("cec2017:f=1,dim=5"),
        "cec2017: parameter 'dim' = 5 has no official data for f=1 (dim = 2, 10, 20, 30, 50, 100 only)");
    EXPECT_EQ(refusal("cec2017:f=29,dim=2"),
              "cec2017: parameter 'dim' = 2 has no official data for f=29 (dim = 10, 30, 50, 100 only)");
    EXPECT_EQ(refusal("cec2017:f=20,dim=2"),
              "cec2017: parameter 'dim' = 2 has no official data for f=20 (dim = 10, 20, 30, 50, 100 only)");
    EXPECT_EQ(refusal("cec2022:f=7,dim=2"),
              "cec2022: parameter 'dim' = 2 has no official data for f=7 (dim = 10, 20 only)");
    EXPECT_EQ(refusal("cec2017:f=31,dim=10"), "cec2017: parameter 'f' = 31 is outside [1, 30]");
    EXPECT_EQ(refusal("cec2022:f=0"), "cec2022: parameter 'f' = 0 is outside [1, 12]");
    EXPECT_EQ(refusal("cec2017:dim=200"), "cec2017: parameter 'dim' = 200 is outside [2, 100]");
    EXPECT_EQ(refusal("cec2022:dim=30"), "cec2022: parameter 'dim' = 30 is outside [2, 20]");
    // The dimension's help says what exists.
    EXPECT_NE(builtin_problems().find("cec2017").parameters[1].help.find(
                  "f=1-10,21-28 in 2, 10, 20, 30, 50, 100; f=11-19,29,30 in 10, 30, 50, 100; f=20 in 10, 20, "
                  "30, 50, 100"),
              std::string::npos);
}

// The availability table (FunctionRecipe::dimensions) is what the shipped data hold: a matrix
// file, and for hybrids (and 2017 F29, F30) a shuffle file, for exactly those dimensions.
TEST(CecProblem, AvailableDimensionsAreThoseOfTheShippedData) {
    for (const auto suite : {cec::Suite::cec2017, cec::Suite::cec2022}) {
        const auto& recipes = cec::recipes(suite);
        for (std::size_t f = 0; f < recipes.size(); ++f) {
            const std::string number = std::to_string(f + 1);
            const bool shuffled = recipes[f].kind == cec::FunctionRecipe::Kind::hybrid ||
                                  (recipes[f].kind == cec::FunctionRecipe::Kind::composition &&
                                   !recipes[f].components[0].hybrid.parts.empty());
            EXPECT_TRUE(cec::has_data_file(suite, "shift_data_" + number + ".txt"));
            for (const int dim : {2, 10, 20, 30, 50, 100}) {
                const std::string d = std::to_string(dim);
                const bool data =
                    cec::has_data_file(suite, "M_" + number + "_D" + d + ".txt") &&
                    (!shuffled || cec::has_data_file(suite, "shuffle_data_" + number + "_D" + d + ".txt"));
                const bool listed = std::find(recipes[f].dimensions.begin(), recipes[f].dimensions.end(),
                                              dim) != recipes[f].dimensions.end();
                EXPECT_EQ(listed, data) << cec::suite_name(suite) << " f=" << number << " dim=" << dim;
            }
        }
    }
}

TEST(CecProblem, SamePointFromManyThreadsGivesTheSameValue) {
    for (const std::string spec : {"cec2017:f=13,dim=30", "cec2017:f=30,dim=50", "cec2022:f=12,dim=20"}) {
        const auto problem = builtin_problems().create(spec);
        const Eigen::Index n = problem->dimension();
        std::vector<Eigen::VectorXd> points;
        for (int k = 0; k < 8; ++k)
            points.push_back(Eigen::VectorXd::LinSpaced(n, -90.0 + k, 80.0 - 3 * k));
        std::vector<double> expected;
        for (const auto& x : points)
            expected.push_back(problem->evaluate(x));
        constexpr int threads = 4;
        std::vector<int> mismatches(threads, 0);
        std::vector<std::thread> pool;
        for (int t = 0; t < threads; ++t)
            pool.emplace_back([&, t] {
                for (int round = 0; round < 200; ++round)
                    for (std::size_t k = 0; k < points.size(); ++k)
                        if (problem->evaluate(points[(k + static_cast<std::size_t>(t)) % points.size()]) !=
                            expected[(k + static_cast<std::size_t>(t)) % points.size()])
                            ++mismatches[static_cast<std::size_t>(t)];
            });
        for (auto& th : pool)
            th.join();
        for (int t = 0; t < threads; ++t)
            EXPECT_EQ(mismatches[static_cast<std::size_t>(t)], 0) << spec << " thread " << t;
    }
}

TEST(CecProblem, WrongLengthIsRefused) {
    const auto problem = builtin_problems().create("cec2022:f=1,dim=10");
    EXPECT_THROW((void)problem->evaluate(Eigen::VectorXd::Zero(20)), std::invalid_argument);
}

} // namespace
} // namespace mhb
