// The structural-bias audit (results/analysis/structural_bias.hpp) on synthetic final points whose
// bias is known: uniform points pass, points squeezed to the centre or pushed to the bounds get
// that verdict, points on one side of the box are "other"; its location tests against scipy; and
// its table and final-points CSV from a study index of f0 runs.
#include <gtest/gtest.h>
#include <stdexcept>

#include "problems/core/rng.hpp"
#include "results/analysis/structural_bias.hpp"
#include "results/tables/structural_bias_table.hpp"

namespace mhb {
namespace {

// 100 runs x 30 dimensions, uniform, then `shape`d coordinate by coordinate.
template <class Shape> std::vector<std::vector<double>> points(Shape shape, std::uint64_t seed = 11) {
    Rng rng(seed);
    std::vector<std::vector<double>> out(100, std::vector<double>(30));
    for (auto& x : out)
        for (double& v : x)
            v = shape(rng.uniform(), rng);
    return out;
}

TEST(StructuralBias, UniformPointsShowNoBias) {
    const BiasAudit a = audit_final_points(points([](double u, Rng&) { return u; }), 0.05);
    EXPECT_EQ(a.verdict, "no bias detected");
    EXPECT_EQ(a.runs, 100U);
    EXPECT_EQ(a.dimensions.size(), 30U);
    EXPECT_EQ(a.ks_rejected + a.ad_rejected, 0U);
    EXPECT_NEAR(a.centre_distance, 0.25, 0.01);
    EXPECT_NEAR(a.near_bound_share, 0.02, 0.01);
}

TEST(StructuralBias, PointsSqueezedToTheCentreAreCentre) {
    const BiasAudit a =
        audit_final_points(points([](double u, Rng&) { return 0.5 + 0.4 * (u - 0.5); }), 0.05);
    EXPECT_EQ(a.verdict, "centre");
    EXPECT_EQ(a.ks_rejected, 30U);
    EXPECT_EQ(a.ad_rejected, 30U);
    EXPECT_LT(a.centre_distance, 0.25);
    EXPECT_EQ(a.near_bound_share, 0.0);
}

TEST(StructuralBias, PointsClampedToTheBoundsAreBounds) {
    // A third of the coordinates pushed out of the box and clamped, as a repair by clamping does.
    const BiasAudit a = audit_final_points(
        points([](double u, Rng& rng) { return rng.uniform() < 1.0 / 3.0 ? (u < 0.5 ? -0.2 : 1.3) : u; }),
        0.05);
    EXPECT_EQ(a.verdict, "bounds");
    EXPECT_EQ(a.ad_rejected, 30U); // a value at 0 or 1 is certain rejection for AD
    EXPECT_GT(a.near_bound_share, 0.3);
    EXPECT_LT(a.near_bound_p, 1e-10);
    // The two bounds, each taking about half (u < 0.5 decides which), add up to the share.
    EXPECT_DOUBLE_EQ(a.near_lower_share + a.near_upper_share, a.near_bound_share);
    EXPECT_GT(a.near_lower_share, 0.12);
    EXPECT_GT(a.near_upper_share, 0.12);
}

TEST(StructuralBias, PointsOnOneSideAreOther) {
    // Uniform on [0, 0.5]: |x - 0.5| is uniform on [0, 0.5], mean 0.25, and only one bound is near.
    const BiasAudit a = audit_final_points(points([](double u, Rng&) { return 0.5 * u; }), 0.05);
    EXPECT_EQ(a.verdict, "other");
    EXPECT_EQ(a.ks_rejected, 30U);
}

TEST(StructuralBias, LocationTestsMatchScipy) {
    // scipy 1.10.1: ttest_1samp(abs(x - 0.5).mean(axis=1), 0.25).pvalue = 0.08023833744600421;
    // binomtest(4, 15, 0.02, alternative='greater').pvalue = 0.00018300568880645981;
    // kstest(x[:, 0], 'uniform', method='exact').pvalue = 0.6245071839999998.
    const std::vector<std::vector<double>> x = {{0.005, 0.40, 0.97},
                                                {0.21, 0.995, 0.58},
                                                {0.66, 0.33, 0.002},
                                                {0.91, 0.12, 0.47},
                                                {0.999, 0.55, 0.28}};
    const BiasAudit a = audit_final_points(x, 0.05);
    EXPECT_NEAR(a.centre_distance, 0.28979999999999995, 1e-15);
    EXPECT_NEAR(a.centre_distance_p, 0.08023833744600421, 1e-12);
    EXPECT_NEAR(a.near_bound_share, 4.0 / 15.0, 1e-15);
    EXPECT_NEAR(a.near_bound_p, 0.00018300568880645981, 1e-15);
    EXPECT_NEAR(a.dimensions[0].ks.p_value, 0.6245071839999998, 1e-12);
    EXPECT_EQ(a.dimensions[0].ks_holm_p, 1.0); // Holm: min(1, 3 x 0.6245)
    EXPECT_EQ(a.verdict, "no bias detected");
}

TEST(StructuralBias, RefusesTooFewPointsOrMixedDimensions) {
    EXPECT_THROW((void)audit_final_points({{0.5, 0.5}}, 0.05), std::invalid_argument);
    EXPECT_THROW((void)audit_final_points({{0.5, 0.5}, {0.5}}, 0.05), std::invalid_argument);
}

RunRecord f0_run(const std::string& problem, const std::string& algorithm, std::int64_t index,
                 std::vector<double> x) {
    RunRecord r;
    r.run_id = index;
    r.algorithm = algorithm;
    r.problem = problem;
    r.run_index = index;
    r.seed = 100 + static_cast<std::uint64_t>(index);
    r.best_f = 0.01;
    r.best_x = std::move(x);
    r.evaluations = 10;
    return r;
}

TEST(StructuralBias, TableAndFinalPointsOfAnF0Study) {
    StudyData study;
    for (std::int64_t i = 0; i < 20; ++i) {
        const double u = (static_cast<double>(i) + 0.5) / 20.0;
        study.runs.push_back(f0_run("f0:dim=2", "spread", i, {u, 1.0 - u}));
        study.runs.push_back(f0_run("f0:dim=2", "centred", i, {0.5 + 0.1 * (u - 0.5), 0.5}));
        study.runs.push_back(f0_run("sphere:dim=2", "spread", i, {u, u}));
    }
    const StudyIndex index(study);
    EXPECT_TRUE(is_bias_problem("f0:dim=2"));
    EXPECT_TRUE(is_bias_problem("f0"));
    EXPECT_FALSE(is_bias_problem("f01:dim=2"));
    const std::optional<Table> t = structural_bias_table(index, 0.05);
    ASSERT_TRUE(t.has_value());
    EXPECT_EQ(t->id, "structural_bias");
    ASSERT_EQ(t->rows.size(), 2U); // the sphere's runs are not audited
    EXPECT_EQ(t->rows[0][0].text, "spread");
    EXPECT_EQ(t->rows[0].back().text, "no bias detected");
    EXPECT_EQ(t->rows[1].back().text, "centre");
    const std::optional<std::string> csv = final_points_csv(index);
    ASSERT_TRUE(csv.has_value());
    EXPECT_EQ(csv->substr(0, csv->find('\n', csv->find('\n') + 1) + 1),
              "problem,algorithm,run,dimension,x\nf0:dim=2,spread,0,1,0.025000000000000001\n");
    StudyData sphere_only;
    for (std::int64_t i = 0; i < 3; ++i)
        sphere_only.runs.push_back(f0_run("sphere:dim=2", "spread", i, {0.1, 0.2}));
    EXPECT_FALSE(structural_bias_table(StudyIndex(sphere_only), 0.05).has_value());
    EXPECT_FALSE(final_points_csv(StudyIndex(sphere_only)).has_value());
}

} // namespace
} // namespace mhb
