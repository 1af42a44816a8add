// Tests of what `mhbench identify --flux-map` computes (problems/fluxmap/): the current errors and
// the residual map against values worked out by hand, the fitted curves against the model they
// invert, and the standard errors and verdicts against a synthetic map whose truth is known.
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "problems/fluxmap/baldor_optimum.hpp"
#include "problems/fluxmap/current_map_fit.hpp"
#include "problems/fluxmap/fit_assessment.hpp"
#include "problems/fluxmap/fitted_curves.hpp"
#include "problems/fluxmap/residual_map.hpp"
#include "problems/fluxmap/synthetic_map.hpp"
#include "problems/problem_registry.hpp"

namespace mhb::fluxmap {
namespace {

// Four points; with SyRM's a_d0 = 2, a_q0 = 3 and the other coefficients 0 the model's currents
// are i_d = 2 psi_d and i_q = 3 psi_q, so the errors are known by hand.
FluxMap four_points() {
    FluxMap m;
    m.i_d = Eigen::ArrayXd(4);
    m.i_q = Eigen::ArrayXd(4);
    m.psi_d = Eigen::ArrayXd(4);
    m.psi_q = Eigen::ArrayXd(4);
    m.i_d << -1, 1, -1, 1;
    m.i_q << -2, -2, 2, 2;
    m.psi_d << -0.5, 0.5, -0.5, 1.0; // errors d: 0, 0, 0, 1
    m.psi_q << -0.5, -1.0, 1.0, 1.0; // errors q: 0.5, -1, 1, 1
    return m;
}

Eigen::VectorXd linear_syrm() {
    Eigen::VectorXd t = Eigen::VectorXd::Zero(9);
    t << 2, 0, 3, 0, 0, 1, 1, 1, 1;
    return t;
}

TEST(FluxMapIdentification, CurrentErrorsAsWorkedOutByHand) {
    const CurrentMap map(Model::syrm, four_points());
    const CurrentErrors e = current_errors(map, linear_syrm());
    EXPECT_DOUBLE_EQ(e.rms_d, std::sqrt(1.0 / 4));
    EXPECT_DOUBLE_EQ(e.rms_q, std::sqrt((0.25 + 1 + 1 + 1) / 4));
    EXPECT_DOUBLE_EQ(e.rms, std::sqrt((0.25 + 1 + 1 + 2) / 4));
    EXPECT_DOUBLE_EQ(e.worst, std::sqrt(2.0));
    EXPECT_EQ(e.worst_point, 3);
}

TEST(FluxMapIdentification, ResidualMapBinsAsWorkedOutByHand) {
    const FluxMap m = four_points();
    Eigen::VectorXd r(8);
    r << 0, 0, 0, 1, 0.5, -1, 1, 1;
    const ResidualMap rm = residual_map(m, r, 7, 9); // two distinct values per axis: 2 x 2 bins
    ASSERT_EQ(rm.rms.rows(), 2);
    ASSERT_EQ(rm.rms.cols(), 2);
    EXPECT_EQ(rm.d_edges, (std::vector<double>{-1, 0, 1}));
    EXPECT_DOUBLE_EQ(rm.rms(0, 0), 0.5);
    EXPECT_DOUBLE_EQ(rm.rms(0, 1), 1.0);
    EXPECT_DOUBLE_EQ(rm.rms(1, 0), 1.0);
    EXPECT_DOUBLE_EQ(rm.rms(1, 1), std::sqrt(2.0));
    const ResidualMap one_bin = residual_map(m, r, 1, 1);
    EXPECT_DOUBLE_EQ(one_bin.rms(0, 0), std::sqrt((0.25 + 1 + 1 + 2) / 4));
    EXPECT_EQ(one_bin.points(0, 0), 4);
}

TEST(FluxMapIdentification, CurveLevelsAreTheGridsOwnValues) {
    Eigen::ArrayXd grid(7);
    grid << -3, -2, -1, -0.0, 1, 2, 3;
    EXPECT_EQ(curve_levels(grid, 3, false), (std::vector<double>{-3, 0, 3}));
    const std::vector<double> positive = curve_levels(grid, 5, true);
    EXPECT_EQ(positive, (std::vector<double>{0, 1, 2, 3})); // four values: no level twice
    EXPECT_FALSE(std::signbit(positive.front()));           // "0 A", never "-0 A"
}

// Every point of every curve is where the model gives the wanted currents, and psi_q(i_q) is odd.
TEST(FluxMapIdentification, FittedCurvesInvertTheModel) {
    const CurrentMap map(Model::pmsyrm, baldor_flux_map());
    const Eigen::VectorXd theta = *baldor_optimum(Model::pmsyrm).x;
    const auto curves = fitted_curves(map, theta, curve_levels(map.map().i_q, 5, true),
                                      curve_levels(map.map().i_d, 5, false), 41);
    ASSERT_EQ(curves.size(), 10u);
    for (const FluxCurve& c : curves) {
        FluxMap at{c.i_d, c.i_q, c.psi_d, c.psi_q};
        ASSERT_TRUE(at.psi_d.allFinite() && at.psi_q.allFinite()) << "level " << c.level;
        Eigen::ArrayXd i_d, i_q;
        CurrentMap(Model::pmsyrm, at).currents(theta, i_d, i_q);
        EXPECT_LE((i_d - c.i_d).abs().maxCoeff(), 1e-6) << "level " << c.level;
        EXPECT_LE((i_q - c.i_q).abs().maxCoeff(), 1e-6) << "level " << c.level;
        if (c.d_axis) { // flux rises with its own current
            EXPECT_TRUE((c.psi_d.tail(40) > c.psi_d.head(40)).all()) << "level " << c.level;
        } else {
            EXPECT_LE((c.psi_q + c.psi_q.reverse()).abs().maxCoeff(), 1e-9) << "level " << c.level;
        }
    }
}

// A synthetic map with 0.02 A of noise: the fit from the truth lands within a few standard errors
// of it, the residual sigma is the noise, and a parameter held by the box is "not determined".
TEST(FluxMapIdentification, StandardErrorsCoverTheTruthOfANoisyMap) {
    const Eigen::VectorXd truth = published_values();
    const CurrentMap map(Model::pmsyrm, synthetic_map(Model::pmsyrm, truth, 0.02, 7));
    const Box box = builtin_problems().create("fluxmap")->bounds();
    const FitResult fit = fit_from(map, box, truth, 2000);
    const FitAssessment a = assess_fit(map, box, fit.theta, {fit.theta});
    EXPECT_NEAR(a.residual_sigma, 0.02, 0.002);
    EXPECT_EQ(a.free_parameters, 14);
    for (const ParameterAssessment& p : a.parameters) {
        const auto j = static_cast<Eigen::Index>(&p - a.parameters.data());
        EXPECT_LE(std::fabs(p.estimate - truth[j]), 5 * p.standard_error) << p.name;
        EXPECT_EQ(p.spread, 0.0);
    }

    Box held = box;
    held.upper[5] = truth[5] - 0.2; // S cannot reach its truth
    const FitResult bounded = fit_from(map, held, truth, 2000);
    const FitAssessment b = assess_fit(map, held, bounded.theta, {bounded.theta});
    EXPECT_EQ(b.free_parameters, 13);
    EXPECT_EQ(b.parameters[5].verdict, Determination::not_determined);
    EXPECT_NE(b.parameters[5].reason.find("on its upper bound"), std::string::npos) << b.parameters[5].reason;
    EXPECT_TRUE(std::isnan(b.parameters[5].standard_error));
}

} // namespace
} // namespace mhb::fluxmap
