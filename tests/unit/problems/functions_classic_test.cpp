// The classic test functions: value at the optimum, values at known points, the usual boxes,
// and the reported optimum. Reference values at known points were worked by hand from each
// function's formula (the simple ones) or computed with an independent Python implementation of
// the formula as printed in its reference (Yao, Liu, Lin 1999 table I; CEC 2005 for Weierstrass;
// Surjanovic and Bingham for Levy), using Python's math module.
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <initializer_list>
#include <map>

#include "problems/functions/classic_function.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

std::unique_ptr<Problem> make_classic_function(const std::string& spec) {
    return builtin_problems().create(spec);
}

Eigen::VectorXd vec(std::initializer_list<double> v) {
    Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
    Eigen::Index i = 0;
    for (const double e : v)
        x[i++] = e;
    return x;
}

double at(const std::string& family, std::initializer_list<double> point, const std::string& extra = "") {
    const auto p = make_classic_function(family + ":dim=" + std::to_string(point.size()) + extra);
    return p->evaluate(vec(point));
}

TEST(ClassicFunctions, SeventeenFamiliesAreRegisteredWithTheirNames) {
    const std::vector<std::string> expected = {
        "sphere",        "ellipsoid",  "schwefel_1_2", "schwefel_2_21", "schwefel_2_22", "step",
        "quartic",       "rosenbrock", "zakharov",     "rastrigin",     "ackley",        "griewank",
        "schwefel_2_26", "levy",       "weierstrass",  "penalized_1",   "penalized_2"};
    EXPECT_EQ(classic_function_names(), expected);
    for (const auto& name : expected) {
        const auto& entry = builtin_problems().find(name);
        EXPECT_FALSE(entry.summary.empty()) << name;
        EXPECT_FALSE(entry.reference.empty()) << name;
        for (const auto& p : entry.parameters)
            EXPECT_FALSE(p.help.empty()) << name << " " << p.name;
    }
}

TEST(ClassicFunctions, ValueAtTheOptimumIsZeroAndIsTheReportedOptimum) {
    for (const auto& name : classic_function_names()) {
        for (const int dim : {2, 10, 30}) {
            const std::string spec =
                name + ":dim=" + std::to_string(dim) + (name == "quartic" ? ",noise=0" : "");
            const auto p = make_classic_function(spec);
            const auto opt = p->known_optimum();
            ASSERT_TRUE(opt.has_value()) << spec;
            ASSERT_TRUE(opt->x.has_value()) << spec;
            EXPECT_TRUE(p->bounds().contains(*opt->x)) << spec;
            EXPECT_NEAR(opt->f, 0.0, 1e-12) << spec;
            EXPECT_EQ(p->evaluate(*opt->x), opt->f) << spec;
        }
    }
}

TEST(ClassicFunctions, UsualBoxesAndOptimaAsPublished) {
    // name -> {lower, upper, optimum coordinate}: Yao, Liu, Lin (1999) table I; CEC 2005 (Weierstrass);
    // Jamil and Yang (2013) (Zakharov); Surjanovic and Bingham (Levy); CEC 2014 (ellipsoid).
    const std::map<std::string, std::array<double, 3>> expected = {
        {"sphere", {-100, 100, 0}},
        {"ellipsoid", {-100, 100, 0}},
        {"schwefel_1_2", {-100, 100, 0}},
        {"schwefel_2_21", {-100, 100, 0}},
        {"schwefel_2_22", {-10, 10, 0}},
        {"step", {-100, 100, 0}},
        {"quartic", {-1.28, 1.28, 0}},
        {"rosenbrock", {-30, 30, 1}},
        {"zakharov", {-5, 10, 0}},
        {"rastrigin", {-5.12, 5.12, 0}},
        {"ackley", {-32, 32, 0}},
        {"griewank", {-600, 600, 0}},
        {"schwefel_2_26", {-500, 500, 420.9687463599821}},
        {"levy", {-10, 10, 1}},
        {"weierstrass", {-0.5, 0.5, 0}},
        {"penalized_1", {-50, 50, -1}},
        {"penalized_2", {-50, 50, 1}}};
    ASSERT_EQ(expected.size(), classic_function_names().size());
    for (const auto& [name, box] : expected) {
        const auto p = make_classic_function(name + ":dim=5");
        EXPECT_EQ(p->dimension(), 5);
        EXPECT_TRUE((p->bounds().lower.array() == box[0]).all()) << name;
        EXPECT_TRUE((p->bounds().upper.array() == box[1]).all()) << name;
        EXPECT_TRUE((p->known_optimum()->x->array() == box[2]).all()) << name;
    }
    // `bound` makes the box [-bound, bound] (the sphere's parameter, kept for every family).
    const auto wide = make_classic_function("sphere:dim=3,bound=7");
    EXPECT_TRUE((wide->bounds().upper.array() == 7.0).all());
    EXPECT_TRUE((wide->bounds().lower.array() == -7.0).all());
    const auto zak = make_classic_function("zakharov:dim=2,bound=20");
    EXPECT_EQ(zak->bounds().lower[0], -20.0);
}

TEST(ClassicFunctions, KnownPointsWorkedByHand) {
    EXPECT_EQ(at("sphere", {1, 2, 3}), 14.0);
    EXPECT_DOUBLE_EQ(at("ellipsoid", {1, 1, 1}), 1.0 + 1e3 + 1e6);
    EXPECT_EQ(at("ellipsoid", {3}), 9.0); // one dimension: weight 1
    EXPECT_EQ(at("schwefel_1_2", {1, 2, 3}), 1.0 + 9.0 + 36.0);
    EXPECT_EQ(at("schwefel_2_21", {1, -5, 3}), 5.0);
    EXPECT_EQ(at("schwefel_2_22", {1, -2, 3}), 6.0 + 6.0);
    EXPECT_EQ(at("step", {0.4, 0.6, -1.6}), 0.0 + 1.0 + 4.0);
    EXPECT_EQ(at("step", {0.49, -0.5, 0.0}), 0.0); // the whole plateau [-0.5, 0.5) is optimal
    EXPECT_EQ(at("quartic", {1, 1}, ",noise=0"), 1.0 + 2.0);
    EXPECT_EQ(at("rosenbrock", {0, 0}), 1.0);
    EXPECT_EQ(at("rosenbrock", {-1, 1}), 4.0);
    EXPECT_DOUBLE_EQ(at("zakharov", {1, 1}), 2.0 + 2.25 + 5.0625);
    EXPECT_NEAR(at("rastrigin", {1, 1}), 2.0, 1e-12);
    EXPECT_NEAR(at("rastrigin", {0.5}), 20.25, 1e-12);
}

TEST(ClassicFunctions, KnownPointsFromAnIndependentImplementation) {
    const auto near = [](double got, double want) {
        EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::fabs(want)));
    };
    near(at("ackley", {1, 1}), 3.6253849384403627);
    near(at("ackley", {0.5, -2, 3}), 8.185902495877848);
    near(at("griewank", {1}), 0.4599476941318603);
    near(at("griewank", {100, -50, 3}), 4.030574007753727);
    near(at("levy", {0, 0}), 0.7158445541169746);
    near(at("levy", {2, -3, 5}), 10.239889628618736);
    near(at("weierstrass", {0.25, -0.1}), 3.1273201571124436);
    near(at("weierstrass", {0.5}), 3.999998092651367);
    near(at("penalized_1", {0, 0}), 8.54120502694725);
    near(at("penalized_1", {11, 2, -20}), 1000183.7103542488);
    near(at("penalized_2", {0, 0}), 0.2);
    near(at("penalized_2", {6, 0.5, -7}), 1711.425);
    near(at("schwefel_2_26", {0, 0}), 837.9657745448675);
    near(at("schwefel_2_26", {-500, 300}), 957.1152136348975);
}

TEST(ClassicFunctions, QuarticNoiseIsUniformAndADeterministicFunctionOfInstanceAndPoint) {
    const auto p = make_classic_function("quartic:dim=3");
    const auto same = make_classic_function("quartic:dim=3");
    const auto other = make_classic_function("quartic:dim=3,instance=2");
    const auto quiet = make_classic_function("quartic:dim=3,noise=0");
    Eigen::VectorXd x = vec({0.1, -0.2, 0.3});
    EXPECT_EQ(p->evaluate(x), p->evaluate(x));
    EXPECT_EQ(p->evaluate(x), same->evaluate(x));
    EXPECT_NE(p->evaluate(x), other->evaluate(x));
    // Over many points the noise (f - noise-free f) lies in [0, 1) with mean 1/2 and variance 1/12.
    double sum = 0.0;
    double sum_sq = 0.0;
    const int n = 4000;
    for (int k = 0; k < n; ++k) {
        x[0] = 0.001 * k;
        const double noise = p->evaluate(x) - quiet->evaluate(x);
        ASSERT_GE(noise, 0.0);
        ASSERT_LT(noise, 1.0);
        sum += noise;
        sum_sq += noise * noise;
    }
    const double mean = sum / n;
    const double variance = sum_sq / n - mean * mean;
    EXPECT_NEAR(mean, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / n)); // 4 standard errors
    EXPECT_NEAR(variance, 1.0 / 12.0, 0.01);
    // The known optimum is the noise-free one.
    EXPECT_EQ(p->known_optimum()->f, 0.0);
}

TEST(ClassicFunctions, BoundsThatExcludeTheOptimumAreRefused) {
    try {
        (void)make_classic_function("schwefel_2_26:dim=2,bound=100");
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("schwefel_2_26: the box [-100, 100]^dim excludes the optimum"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW((void)make_classic_function("rosenbrock:dim=2,bound=0.5"), std::invalid_argument);
    EXPECT_THROW((void)make_classic_function("rosenbrock:dim=1"),
                 std::invalid_argument); // needs two coordinates
}

} // namespace
} // namespace mhb

namespace mhb {
namespace {

// Issue 9: a huge box made the product term overflow to inf before a zero coordinate, and
// inf x 0 gave NaN at an in-box point. A zero factor makes the product 0, whatever came before.
TEST(ClassicFunctions, Schwefel222IsFiniteOrPlusInfinityNeverNan) {
    const auto p = builtin_problems().create("schwefel_2_22:dim=30,bound=1e12");
    Eigen::VectorXd x = Eigen::VectorXd::Constant(30, 1e12);
    x[29] = 0.0;
    EXPECT_EQ(p->evaluate(x), 29e12);
    x[29] = 1e12;
    EXPECT_EQ(p->evaluate(x), std::numeric_limits<double>::infinity()); // a legal worst value
}

} // namespace
} // namespace mhb
