// Tests of the `fluxmap` problem family (problems/fluxmap/): the objective against the formulas
// written out point by point, the model's symmetry, synthetic maps with a known truth, the shipped
// best-known optimum, bound overrides and the registry's checks.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "problems/core/sha256.hpp"
#include "problems/fluxmap/baldor_optimum.hpp"
#include "problems/fluxmap/current_map.hpp"
#include "problems/fluxmap/current_map_fit.hpp"
#include "problems/fluxmap/synthetic_map.hpp"
#include "problems/problem_registry.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {

struct FluxPoint {
    double i_d, i_q, psi_d, psi_q;
};

// The shipped map read with nothing of problems/fluxmap.
std::vector<FluxPoint> flux_shipped_points() {
    std::ifstream in(std::string(MHB_SOURCE_DIR) + "/problems/fluxmap/data/baldor-ecs101m0h7ef4-400rpm.csv");
    std::string line;
    std::getline(in, line);
    std::vector<FluxPoint> points;
    for (FluxPoint p{}; std::getline(in, line);) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream(line) >> p.i_d >> p.i_q >> p.psi_d >> p.psi_q;
        points.push_back(p);
    }
    return points;
}

// The objective as the papers write it, with std::pow, one point at a time.
double flux_plain_objective(const std::vector<FluxPoint>& points, const std::vector<double>& t) {
    double sum = 0;
    for (const FluxPoint& p : points) {
        const double d = std::fabs(p.psi_d), q = std::fabs(p.psi_q);
        const double g_d =
            t[0] + t[1] * std::pow(d, t[5]) + t[4] / (t[8] + 2) * std::pow(d, t[7]) * std::pow(q, t[8] + 2);
        const double g_q =
            t[2] + t[3] * std::pow(q, t[6]) + t[4] / (t[7] + 2) * std::pow(d, t[7] + 2) * std::pow(q, t[8]);
        double i_d = g_d * p.psi_d, i_q = g_q * p.psi_q;
        if (t.size() == 14) {
            const double psi_b = p.psi_d - t[9];
            const double s = std::sqrt(psi_b * psi_b + t[13] * p.psi_q * p.psi_q);
            const double g_b = t[10] * std::pow(s, t[12]) / (1 + t[11] * std::pow(s, t[12]));
            i_d += g_b * psi_b;
            i_q += t[13] * g_b * p.psi_q;
        }
        sum += (i_d - p.i_d) * (i_d - p.i_d) + (i_q - p.i_q) * (i_q - p.i_q);
    }
    return sum;
}

const std::vector<double> flux_odd_theta = {3.1, 25.0, 6.2,  3.3,  38.0, 4.3, 5.7,
                                            0.8, 1.3,  0.77, 90.0, 1.4,  2.6, 0.15};

Eigen::VectorXd flux_theta(const std::vector<double>& v, std::size_t n) {
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(n));
}

std::string fluxmap_error_of(const std::string& spec) {
    try {
        (void)builtin_problems().create(spec);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "no error";
}

TEST(FluxMapProblem, ObjectiveMatchesThePapersFormulasPointByPoint) {
    const auto points = flux_shipped_points();
    ASSERT_EQ(points.size(), 567u);
    const auto pm = builtin_problems().create("fluxmap");
    const auto syrm = builtin_problems().create("fluxmap:model=syrm");
    ASSERT_EQ(pm->dimension(), 14);
    ASSERT_EQ(syrm->dimension(), 9);
    const Eigen::VectorXd published = fluxmap::published_values();
    const std::vector<double> published_list(published.data(), published.data() + published.size());
    for (const std::vector<double>& t : {flux_odd_theta, published_list}) {
        const std::vector<double> t9(t.begin(), t.begin() + 9);
        const double want_pm = flux_plain_objective(points, t), want_syrm = flux_plain_objective(points, t9);
        EXPECT_NEAR(pm->evaluate(flux_theta(t, 14)), want_pm, 1e-12 * want_pm);
        EXPECT_NEAR(syrm->evaluate(flux_theta(t, 9)), want_syrm, 1e-12 * want_syrm);
    }
}

TEST(FluxMapProblem, ShippedMapIsTheRecordedFile) {
    const auto bytes = test_support::read_text(std::string(MHB_SOURCE_DIR) + "/problems/fluxmap/data/" +
                                               fluxmap::baldor_map_name);
    EXPECT_EQ(sha256_hex(bytes), fluxmap::baldor_map_sha256);
    EXPECT_EQ(fluxmap::baldor_flux_map().size(), 567);
    EXPECT_EQ(flux_shipped_points().back().psi_q, fluxmap::baldor_flux_map().psi_q[566]);
}

TEST(FluxMapProblem, ZeroExponentIsOneAtZeroFlux) {
    // psi_q = 0 on the i_q = 0 row: q^0 must be 1 there (std::pow's convention), not NaN.
    std::vector<double> t = flux_odd_theta;
    t[8] = 0.0; // V
    const auto pm = builtin_problems().create("fluxmap");
    const double want = flux_plain_objective(flux_shipped_points(), t);
    EXPECT_NEAR(pm->evaluate(flux_theta(t, 14)), want, 1e-12 * want);
}

TEST(FluxMapProblem, IqIsOddInPsiqAndIdEven) {
    fluxmap::FluxMap map = fluxmap::baldor_flux_map();
    fluxmap::FluxMap mirrored = map;
    mirrored.psi_q = -map.psi_q;
    Eigen::ArrayXd id, iq, id_m, iq_m;
    fluxmap::CurrentMap(fluxmap::Model::pmsyrm, map).currents(flux_theta(flux_odd_theta, 14), id, iq);
    fluxmap::CurrentMap(fluxmap::Model::pmsyrm, mirrored)
        .currents(flux_theta(flux_odd_theta, 14), id_m, iq_m);
    EXPECT_TRUE((iq_m == -iq).all());
    EXPECT_TRUE((id_m == id).all());
}

TEST(FluxMapProblem, SyntheticNoiselessMapIsZeroAtTheTruth) {
    for (const char* spec : {"fluxmap:synthetic=on", "fluxmap:synthetic=on,model=syrm"}) {
        const auto problem = builtin_problems().create(spec);
        ASSERT_TRUE(problem->true_parameters().has_value());
        const Eigen::VectorXd truth = *problem->true_parameters();
        EXPECT_EQ(truth, fluxmap::published_values().head(problem->dimension()));
        EXPECT_LE(problem->evaluate(truth), 1e-20) << spec;
        ASSERT_TRUE(problem->known_optimum().has_value());
        EXPECT_EQ(problem->known_optimum()->f, 0.0);
        EXPECT_GT(problem->evaluate(flux_theta(flux_odd_theta, static_cast<std::size_t>(truth.size()))), 1.0);
    }
}

TEST(FluxMapProblem, SyntheticNoiseIsSeededAndHasItsVariance) {
    const auto a = builtin_problems().create("fluxmap:synthetic=on,noise=0.1,seed=3");
    const auto b = builtin_problems().create("fluxmap:synthetic=on,noise=0.1,seed=3");
    const auto c = builtin_problems().create("fluxmap:synthetic=on,noise=0.1,seed=4");
    const Eigen::VectorXd truth = *a->true_parameters();
    EXPECT_EQ(a->evaluate(truth), b->evaluate(truth));
    EXPECT_NE(a->evaluate(truth), c->evaluate(truth));
    // 2 x 567 residuals of variance 0.01: the sum is 11.34 within a few of its std (0.48).
    EXPECT_NEAR(a->evaluate(truth), 11.34, 2.0);
    EXPECT_FALSE(a->known_optimum().has_value());
}

TEST(FluxMapProblem, TruthIsGivenPerParameter) {
    const auto p =
        builtin_problems().create("fluxmap:synthetic=on,model=syrm,truth=4/30/6/3/40/4.5/5.5/1.5/0.5");
    EXPECT_EQ(*p->true_parameters(), flux_theta({4, 30, 6, 3, 40, 4.5, 5.5, 1.5, 0.5}, 9));
    EXPECT_NE(
        fluxmap_error_of("fluxmap:synthetic=on,model=syrm,truth=1/2").find("has 2 values; model=syrm has 9"),
        std::string::npos);
    EXPECT_NE(fluxmap_error_of("fluxmap:truth=1/2").find("'truth' applies to synthetic=on only"),
              std::string::npos);
}

TEST(FluxMapProblem, ShippedOptimumIsWhereItIsSaid) {
    for (const auto model : {fluxmap::Model::syrm, fluxmap::Model::pmsyrm}) {
        const auto problem =
            builtin_problems().create(model == fluxmap::Model::syrm ? "fluxmap:model=syrm" : "fluxmap");
        const auto known = problem->known_optimum();
        ASSERT_TRUE(known.has_value() && known->x.has_value());
        EXPECT_TRUE(problem->bounds().contains(*known->x));
        EXPECT_NEAR(problem->evaluate(*known->x), known->f, 1e-13 * known->f);
        EXPECT_EQ(problem->parameter_names(), fluxmap::parameter_names(model));
        EXPECT_EQ(problem->warnings().size(), model == fluxmap::Model::syrm ? 1u : 0u);
    }
}

TEST(FluxMapProblem, FewStartsReFindTheShippedOptimum) {
    const auto problem = builtin_problems().create("fluxmap");
    const fluxmap::CurrentMap map(fluxmap::Model::pmsyrm, fluxmap::baldor_flux_map());
    const fluxmap::FitResult fit = fluxmap::fit_multistart(map, problem->bounds(), {4, 1, 2000});
    const double f_star = fluxmap::baldor_optimum(fluxmap::Model::pmsyrm).f;
    EXPECT_LE(fit.f, f_star * (1 + 1e-9));
    EXPECT_GE(fit.reached(1e-9), 1);
}

TEST(FluxMapProblem, BoundsAreOverriddenAsPmsmTakesThem) {
    const auto p = builtin_problems().create("fluxmap:S=1:8,k_q=0.05:0.5");
    EXPECT_EQ(p->bounds().lower[5], 1.0);
    EXPECT_EQ(p->bounds().upper[5], 8.0);
    EXPECT_EQ(p->bounds().lower[13], 0.05);
    EXPECT_EQ(p->bounds().upper[13], 0.5);
    EXPECT_EQ(p->bounds().upper[0], 20.0);
    EXPECT_NE(fluxmap_error_of("fluxmap:S=8:1").find("'S' = 8:1 needs lo < hi"), std::string::npos);
    EXPECT_NE(fluxmap_error_of("fluxmap:a_dd=5").find("'a_dd' = 5 is not of the form lo:hi"),
              std::string::npos);
    EXPECT_NE(fluxmap_error_of("fluxmap:U=-1:2").find("'U' = -1:2 needs lo >= 0"), std::string::npos);
    EXPECT_NE(fluxmap_error_of("fluxmap:model=syrm,W=1:2").find("'W' is a parameter of model=pmsyrm"),
              std::string::npos);
    // A box that excludes theta* drops the known optimum rather than report a wrong one.
    EXPECT_FALSE(builtin_problems().create("fluxmap:a_d0=15:20")->known_optimum().has_value());
}

} // namespace
} // namespace mhb
