// The effect of each component (results/factorial_effects.*): detection of full 2^k designs from
// full specs, the effects of a hand-computed 2^3 example with known effects (p-values from SciPy,
// Holm by hand), the response scales, and the analysis of a study's records.
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

#include "results/analysis/factorial_effects.hpp"
#include "results/store/study_index.hpp"
#include "results/tables/effects_table.hpp"

namespace mhb {
namespace {

// The 8 ITLBO variants of the ablation grid: full spec and canonical spec of variant m, where
// bit 0 = obl, bit 1 = stepwise, bit 2 = tutorial (the factors sorted by name).
std::string full_spec(std::size_t m) {
    const auto on = [&](std::size_t j) {
        return ((m >> j) & 1U) != 0 ? std::string("on") : std::string("off");
    };
    return "itlbo:np=50,obl=" + on(0) +
           ",obl_bounds=static,obl_greedy=off,p=0.1,r=coordinate,stepwise=" + on(1) + ",tutorial=" + on(2);
}
std::string canonical(std::size_t m) {
    std::string params;
    for (std::size_t j = 0; j < 3; ++j)
        if (((m >> j) & 1U) == 0)
            params += std::string(params.empty() ? "" : ",") +
                      (j == 0   ? "obl"
                       : j == 1 ? "stepwise"
                                : "tutorial") +
                      "=off";
    return params.empty() ? "itlbo" : "itlbo:" + params;
}

TEST(FactorialDesignDetection, FindsTheFullTwoToTheThreeInAnyOrder) {
    std::vector<std::string> specs;
    std::vector<std::string> full;
    for (std::size_t m : {5U, 0U, 7U, 2U, 1U, 6U, 3U, 4U}) {
        specs.push_back(canonical(m));
        full.push_back(full_spec(m));
    }
    const DesignCandidate c = detect_factorial_design(specs, full);
    ASSERT_TRUE(c.design.has_value()) << c.why_not;
    EXPECT_EQ(c.design->factors, (std::vector<std::string>{"obl", "stepwise", "tutorial"}));
    EXPECT_EQ(c.design->algorithms[7], "itlbo");
    EXPECT_EQ(c.design->algorithms[0], "itlbo:obl=off,stepwise=off,tutorial=off");
    EXPECT_EQ(c.design->algorithms[4], "itlbo:obl=off,stepwise=off"); // tutorial on only
    EXPECT_EQ(c.design->description(), "itlbo: obl x stepwise x tutorial (2^3)");
    // k = 1: two variants differing in one switch.
    const DesignCandidate one =
        detect_factorial_design({"itlbo", "itlbo:obl=off"}, {full_spec(7), full_spec(6)});
    ASSERT_TRUE(one.design.has_value()) << one.why_not;
    EXPECT_EQ(one.design->factors, std::vector<std::string>{"obl"});
}

TEST(FactorialDesignDetection, RefusesWhatIsNotAFullFactorial) {
    std::vector<std::string> specs;
    std::vector<std::string> full;
    for (std::size_t m = 0; m < 8; ++m)
        if (m != 3) {
            specs.push_back(canonical(m));
            full.push_back(full_spec(m));
        }
    const DesignCandidate missing = detect_factorial_design(specs, full);
    EXPECT_FALSE(missing.design.has_value());
    EXPECT_NE(missing.why_not.find("missing: obl=on,stepwise=on,tutorial=off"), std::string::npos)
        << missing.why_not;

    // A varying parameter that is not on/off.
    const DesignCandidate numeric = detect_factorial_design(
        {"pso", "pso:w=0.7", "pso:obl=on", "pso:obl=on,w=0.7"},
        {"pso:obl=off,w=0.5", "pso:obl=off,w=0.7", "pso:obl=on,w=0.5", "pso:obl=on,w=0.7"});
    EXPECT_FALSE(numeric.design.has_value());
    EXPECT_NE(numeric.why_not.find("parameter 'w' varies (0.5, 0.7) and is not an on/off switch"),
              std::string::npos)
        << numeric.why_not;

    // Two algorithm names.
    const DesignCandidate names = detect_factorial_design(
        {"tlbo", "itlbo:tutorial=off"}, {"tlbo:np=50,tutorial=on", "itlbo:np=50,tutorial=off"});
    EXPECT_FALSE(names.design.has_value());
    EXPECT_NE(names.why_not.find("different algorithms"), std::string::npos) << names.why_not;

    // The same combination twice (two labels of one configuration).
    const DesignCandidate twice = detect_factorial_design({"itlbo", "itlbo:obl=off", "itlbo:label=x"},
                                                          {full_spec(7), full_spec(6), full_spec(7)});
    EXPECT_FALSE(twice.design.has_value());
    EXPECT_NE(twice.why_not.find("appears twice"), std::string::npos) << twice.why_not;
    EXPECT_FALSE(detect_factorial_design({"itlbo"}, {full_spec(7)}).design.has_value());
    EXPECT_FALSE(detect_factorial_design({"itlbo", "itlbo:np=50"}, {full_spec(7), full_spec(7)}).design);
}

// The hand-computed example: in block b (10 blocks) the response of variant m is
//   y = (3 + b) + sum over effects E of E_b / 2 * (contrast sign of E for m),
// with per-block effects T_b (tutorial), S_b (stepwise), O_b (obl), TS_b, TO_b = 0 and SO_b. In a
// full 2^3 design the contrasts are orthogonal, so each effect estimate in block b is exactly E_b
// (all values are multiples of 1/32: the arithmetic is exact).
const std::vector<double> T = {-2.0, -2.125, -2.25, -2.375, -2.5, -2.625, -2.75, -2.875, -3.0, -3.125};
const std::vector<double> S = {0.5, 0.75, -0.125, 1.0, 0.625, 0.875, 1.125, 0.375, 1.25, 1.5};
const std::vector<double> O = {0.25, -0.5, 0.75, -1.0, 1.25, -1.5, 1.75, -2.0, 2.25, -2.5};
const std::vector<double> TS = {-0.25,    -0.28125, -0.3125,  -0.34375, -0.375,
                                -0.40625, -0.4375,  -0.46875, -0.5,     -0.53125};
const std::vector<double> SO = {0.125, 0.25, -0.375, 0.5, -0.625, 0.75, 0.875, -1.0, 1.125, 1.25};

std::vector<std::vector<double>> example_blocks() {
    std::vector<std::vector<double>> blocks;
    for (std::size_t b = 0; b < 10; ++b) {
        std::vector<double> y;
        for (std::size_t m = 0; m < 8; ++m) {
            const double so = (m & 1U) ? 1.0 : -1.0; // obl
            const double ss = (m & 2U) ? 1.0 : -1.0; // stepwise
            const double st = (m & 4U) ? 1.0 : -1.0; // tutorial
            y.push_back(3.0 + static_cast<double>(b) + T[b] / 2 * st + S[b] / 2 * ss + O[b] / 2 * so +
                        TS[b] / 2 * st * ss + SO[b] / 2 * ss * so);
        }
        blocks.push_back(y);
    }
    return blocks;
}

TEST(FactorialEffects, HandComputedTwoToTheThreeExample) {
    const EffectAnalysis a = analyse_factorial_blocks(example_blocks(), {"obl", "stepwise", "tutorial"},
                                                      ResponseScale::log10_gap, 0.05);
    ASSERT_EQ(a.effects.size(), 6u);
    EXPECT_EQ(a.blocks, 10u);
    const std::vector<std::string> names = {
        "obl", "stepwise", "tutorial", "obl x stepwise", "obl x tutorial", "stepwise x tutorial"};
    const std::vector<const std::vector<double>*> truth = {&O, &S, &T, &SO, nullptr, &TS};
    for (std::size_t e = 0; e < 6; ++e) {
        EXPECT_EQ(a.effects[e].name, names[e]);
        for (std::size_t b = 0; b < 10; ++b)
            EXPECT_EQ(a.effects[e].per_block[b], truth[e] ? (*truth[e])[b] : 0.0)
                << names[e] << " block " << b;
    }
    // Means and medians by hand.
    EXPECT_DOUBLE_EQ(a.effects[2].mean, -2.5625);
    EXPECT_DOUBLE_EQ(a.effects[2].median, -2.5625);
    EXPECT_DOUBLE_EQ(a.effects[1].mean, 0.7875);
    EXPECT_DOUBLE_EQ(a.effects[1].median, 0.8125);
    EXPECT_DOUBLE_EQ(a.effects[0].mean, -0.125);
    EXPECT_DOUBLE_EQ(a.effects[5].mean, -0.390625);
    EXPECT_EQ(a.effects[4].mean, 0.0);
    // Signed-rank against 0: scipy.stats.wilcoxon(E, method='exact') gives
    //   O 0.845703125, S 0.00390625, T 0.001953125, SO 0.275390625, TS 0.001953125 (TO: all zero, p = 1);
    // V = sum of the positive ranks: O 25, S 54, T 0, SO 39, TS 0.
    const std::vector<double> p = {0.845703125, 0.00390625, 0.001953125, 0.275390625, 1.0, 0.001953125};
    const std::vector<double> v = {25, 54, 0, 39, 0, 0};
    for (std::size_t e = 0; e < 6; ++e) {
        EXPECT_DOUBLE_EQ(a.effects[e].test.p_value, p[e]) << names[e];
        EXPECT_EQ(a.effects[e].test.statistic, v[e]) << names[e];
    }
    EXPECT_EQ(a.effects[2].test.name, "Wilcoxon signed-rank, exact");
    // Holm over the six (R: p.adjust(p, "holm")): sorted T, TS, S, SO, O, TO get x6, x5, x4, x3, x2,
    // x1 with running maxima: T 0.01171875, TS max(0.01171875, 0.009765625), S 0.015625,
    // SO 0.826171875, O 1 (capped), TO 1.
    const std::vector<double> holm = {1.0, 0.015625, 0.01171875, 0.826171875, 1.0, 0.01171875};
    for (std::size_t e = 0; e < 6; ++e)
        EXPECT_DOUBLE_EQ(a.effects[e].adjusted_p, holm[e]) << names[e];
    EXPECT_EQ(a.effects[2].reading, "tutorial on lowers log10(f - f*) by 2.56: helps");
    EXPECT_EQ(a.effects[1].reading.rfind("stepwise on raises log10(f - f*) by 0.78", 0), 0u)
        << a.effects[1].reading;
    EXPECT_EQ(a.effects[0].reading, "no significant effect");
    EXPECT_EQ(a.effects[4].reading, "no significant effect");
    EXPECT_EQ(a.effects[5].reading,
              "interaction -0.391: stepwise helps more (or hurts less) with tutorial on, and vice versa");
    // Level means: mean of 3 + b is 7.5; tutorial on adds mean(T)/2, off subtracts it.
    const auto level = [&](std::size_t f, bool l) {
        for (const auto& m : a.level_means)
            if (m.factor == f && m.level == l && !m.second_factor)
                return m.mean;
        ADD_FAILURE();
        return 0.0;
    };
    EXPECT_DOUBLE_EQ(level(2, true), 7.5 - 2.5625 / 2);
    EXPECT_DOUBLE_EQ(level(2, false), 7.5 + 2.5625 / 2);
    // Pair (stepwise on, tutorial on): 7.5 + (mean S + mean T + mean TS) / 2.
    for (const auto& m : a.level_means)
        if (m.factor == 1 && m.second_factor == 2u && m.level && m.second_level) {
            EXPECT_DOUBLE_EQ(m.mean, 7.5 + (0.7875 - 2.5625 - 0.390625) / 2);
        }
    EXPECT_EQ(a.level_means.size(), 6u + 12u);
}

TEST(FactorialEffects, ResponseScaleAndFloor) {
    EXPECT_EQ(gap_floor(0.0), 1e-300);
    EXPECT_EQ(gap_floor(2.0), 8.0 * std::numeric_limits<double>::epsilon());
    EXPECT_DOUBLE_EQ(gap_response(1e-3, 0.0), -3.0);
    EXPECT_DOUBLE_EQ(gap_response(0.0, 0.0), -300.0);                             // at the optimum
    EXPECT_DOUBLE_EQ(gap_response(2.0 - 1e-15, 2.0), std::log10(gap_floor(2.0))); // rounding below f*
    EXPECT_TRUE(std::isfinite(gap_response(2.0, 2.0)));
    EXPECT_THROW((void)analyse_factorial_blocks({{1.0, 2.0, 3.0}}, {"a"}, ResponseScale::rank, 0.05),
                 std::invalid_argument);
}

// A study of the 8 variants: problem "sphere" (f* = 0, response log10 f) and "black-box" (no f*:
// ranks), 6 run indices with common seeds; run 5 of one variant failed on the sphere.
StudyData ablation_study() {
    StudyData data;
    for (std::size_t m = 0; m < 8; ++m) {
        // Appended, not "v" + ...: GCC 12 warns falsely (-Wstringop-overflow) on that in a unity batch.
        std::string label = "v";
        label += std::to_string(m);
        data.algorithms.push_back({canonical(m), label, full_spec(m)});
    }
    std::int64_t id = 0;
    for (const char* problem : {"sphere:dim=2", "black-box"})
        for (std::size_t m = 0; m < 8; ++m)
            for (std::int64_t i = 0; i < 6; ++i) {
                RunRecord r;
                r.run_id = id++;
                r.algorithm = canonical(m);
                r.problem = problem;
                r.budget = "iterations=10";
                r.run_index = i;
                r.seed = 100 + static_cast<std::uint64_t>(i);
                const bool tutorial = (m & 4U) != 0;
                const bool obl = (m & 1U) != 0;
                // log10 f = -1 - (2 + 0.1 i) [tutorial on] + 0.5 [obl on] + 0.01 i.
                const double di = static_cast<double>(i);
                const double y = -1.0 - (tutorial ? 2.0 + 0.1 * di : 0.0) + (obl ? 0.5 : 0.0) + 0.01 * di;
                r.best_f = std::pow(10.0, y);
                if (std::string(problem) == "sphere:dim=2")
                    r.f_opt = 0.0;
                r.ok = !(std::string(problem) == "sphere:dim=2" && m == 3 && i == 5);
                data.runs.push_back(r);
            }
    return data;
}

TEST(FactorialEffects, FromAStudysRecordsPerProblemAndPooled) {
    const StudyData data = ablation_study();
    const StudyIndex index(data);
    const auto candidates = find_factorial_designs(index);
    ASSERT_EQ(candidates.size(), 1u);
    ASSERT_TRUE(candidates[0].design.has_value()) << candidates[0].why_not;
    const auto analyses = factorial_effects(index, *candidates[0].design, 0.05);
    ASSERT_EQ(analyses.size(), 3u); // two problems and all problems
    const EffectAnalysis& sphere = analyses[0];
    EXPECT_EQ(sphere.problem, "sphere:dim=2");
    EXPECT_EQ(sphere.scale, ResponseScale::log10_gap);
    EXPECT_EQ(sphere.blocks, 5u); // run 5 lacks a variant
    EXPECT_EQ(sphere.left_out, 1u);
    EXPECT_TRUE(sphere.paired);
    EXPECT_NEAR(sphere.effects[2].mean, -2.2, 1e-9); // tutorial: -(2 + 0.1 i) over i = 0..4
    EXPECT_NEAR(sphere.effects[0].mean, 0.5, 1e-9);  // obl
    EXPECT_NEAR(sphere.effects[1].mean, 0.0, 1e-9);  // stepwise
    // Five distinct negative effects: exact p = 2/32 = 0.0625, never below 0.05: too few blocks to tell.
    EXPECT_DOUBLE_EQ(sphere.effects[2].test.p_value, 0.0625);
    EXPECT_EQ(sphere.effects[2].reading, "no significant effect");
    const EffectAnalysis& ranks = analyses[1];
    EXPECT_EQ(ranks.scale, ResponseScale::rank);
    EXPECT_EQ(ranks.blocks, 6u);
    // Ranks of the 8 variants by f: tutorial on takes ranks 1-4, so its effect is -4 in every block;
    // obl on is worse within each tutorial level: +2.
    EXPECT_DOUBLE_EQ(ranks.effects[2].mean, -4.0);
    EXPECT_DOUBLE_EQ(ranks.effects[0].mean, 2.0);
    // Six tied effects: the normal approximation with tie and continuity correction, as R (which
    // warns it cannot compute an exact p with ties); scipy.stats.wilcoxon([-4.0] * 6,
    // method='approx', correction=True) -> 0.019656157250169892.
    EXPECT_FALSE(ranks.effects[2].test.exact);
    EXPECT_NEAR(ranks.effects[2].test.p_value, 0.019656157250169892, 1e-12);
    const EffectAnalysis& all = analyses[2];
    EXPECT_EQ(all.problem, "all problems (2)");
    EXPECT_EQ(all.scale, ResponseScale::rank); // black-box has no f*
    EXPECT_EQ(all.blocks, 11u);
    EXPECT_EQ(all.effects[2].reading, "tutorial on lowers the within-block rank by 4: helps");
    EXPECT_EQ(all.effects[0].reading, "obl on raises the within-block rank by 2: hurts");

    std::vector<DesignEffects> designs = {{*candidates[0].design, analyses}};
    const auto table = effects_table(designs, {}, 0.05);
    ASSERT_TRUE(table.has_value());
    EXPECT_EQ(table->rows.size(), 18u);
    EXPECT_NE(table->caption.find("Wilcoxon signed-rank"), std::string::npos);
    EXPECT_NE(table->caption.find("Holm"), std::string::npos);
    EXPECT_NE(table->caption.find("1 on sphere:dim=2"), std::string::npos) << table->caption;
    const std::string csv = effect_means_csv(designs);
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "design,problem,scale,blocks,factor,level,factor2,level2,mean_response");
}

TEST(FactorialEffects, ExtraVariantOrUnpairedSeedsAreSaid) {
    StudyData data = ablation_study();
    // Per-algorithm seeds: the blocks are no longer paired (the analysis still runs, and says so).
    for (auto& r : data.runs)
        r.seed = static_cast<std::uint64_t>(r.run_id);
    {
        const StudyIndex index(data);
        EXPECT_FALSE(index.paired("sphere:dim=2"));
        const auto analyses = factorial_effects(index, *find_factorial_designs(index)[0].design, 0.05);
        EXPECT_FALSE(analyses[0].paired);
    }
    // A ninth variant with another np: the group is no longer a design, and the table's note says why.
    data.algorithms.push_back({"itlbo:np=30", "np30",
                               "itlbo:np=30,obl=on,obl_bounds=static,obl_greedy=off,p=0.1,"
                               "r=coordinate,stepwise=on,tutorial=on"});
    RunRecord extra = data.runs.front();
    extra.algorithm = "itlbo:np=30";
    extra.run_id = 1000;
    data.runs.push_back(extra);
    const StudyIndex index(data);
    const auto candidates = find_factorial_designs(index);
    ASSERT_EQ(candidates.size(), 1u);
    EXPECT_FALSE(candidates[0].design.has_value());
    EXPECT_NE(candidates[0].why_not.find("parameter 'np' varies"), std::string::npos)
        << candidates[0].why_not;
    EXPECT_FALSE(effects_table({}, candidates, 0.05).has_value());
}

} // namespace
} // namespace mhb
