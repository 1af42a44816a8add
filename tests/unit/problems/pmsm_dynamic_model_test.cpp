// Tests of the dynamic identification model (problems/pmsm/dynamic_model.*): its equations on
// crafted data, the segment rule (no equation across a time jump), smoothing, the dead-time
// regressor, and the least-squares optimum against the independent reference values in
// tests/data/pmsm/expected_dynamic.csv.
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "problems/core/rng.hpp"
#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/dynamic_model.hpp"
#include "problems/pmsm/linear_model.hpp"
#include "problems/pmsm/segments.hpp"
#include "support/data.hpp"

namespace mhb::pmsm {
namespace {

using mhb::test_support::pmsm_data_dir;
constexpr double Ts = 1e-4;

// The shared files have no `injected` column: the reader tells the states by |id| > 1 A, and every
// one of them has samples on both sides (the dynamic model itself ignores the state).
Dataset read(const std::string& file) {
    return read_dataset_csv(pmsm_data_dir + file, DatasetReadOptions{});
}

struct ExpectedRow {
    std::string file;
    Eigen::Vector4d theta_ls, truth;
    double f_ls = 0;
};

std::vector<ExpectedRow> read_expected_dynamic() {
    std::ifstream in(pmsm_data_dir + "expected_dynamic.csv");
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "file,Rs_ls,Ld_ls,Lq_ls,psi_ls,f_ls,Rs_true,Ld_true,Lq_true,psi_true");
    std::vector<ExpectedRow> rows;
    while (std::getline(in, line)) {
        if (line.empty())
            continue;
        std::stringstream row(line);
        ExpectedRow e;
        std::getline(row, e.file, ',');
        std::string cell;
        double v[9];
        for (double& x : v) {
            std::getline(row, cell, ',');
            x = std::stod(cell);
        }
        e.theta_ls = Eigen::Vector4d(v[0], v[1], v[2], v[3]);
        e.f_ls = v[4];
        e.truth = Eigen::Vector4d(v[5], v[6], v[7], v[8]);
        rows.push_back(e);
    }
    return rows;
}

// Every row of expected_dynamic.csv (the four `_tr` files and the IPM `_ss` files, whose time
// jump must be skipped): the parameters to 1e-9 relative (measured: 3e-13 at most), and f to 1e-9
// (measured: 8e-10 at most) except on the clean `_ss` file. There f* = 3.1e-13 is a sum of
// squares of 2e-8 V residuals of 80 V terms, which double precision evaluates to ~5e-9 only: the
// file's own f_ls is 4.1e-9 above the exact-arithmetic value of its theta (measured with
// __float128), and ours, at a theta 1.4e-13 away, is 1.8e-9 above it. The direct sum at the
// file's theta reproduces its f_ls, which shows both sides form the same equations.
TEST(PmsmDynamicModel, ReproducesExpectedDynamicCsv) {
    const auto rows = read_expected_dynamic();
    ASSERT_EQ(rows.size(), 6u);
    for (const ExpectedRow& e : rows) {
        SCOPED_TRACE(e.file);
        const Dataset d = read(e.file);
        ASSERT_EQ(d.size(), 300u);
        const LinearModel model = dynamic_model({d}, {e.file});
        const bool has_jump = e.file.find("_ss") != std::string::npos;
        EXPECT_EQ(model.d_rows, has_jump ? 298 : 299);
        EXPECT_EQ(model.equations(), 2 * model.d_rows);
        const LinearFit fit = fit_linear_model(model);
        for (Eigen::Index j = 0; j < 4; ++j)
            EXPECT_NEAR(fit.theta[j] / e.theta_ls[j], 1.0, 1e-9) << model.parameter_names[std::size_t(j)];
        const double f_tolerance = e.f_ls < 1e-9 ? 5e-9 : 1e-9;
        EXPECT_NEAR(fit.f / e.f_ls, 1.0, f_tolerance);
        EXPECT_NEAR(model.fitness(e.theta_ls) / e.f_ls, 1.0, f_tolerance);
        ASSERT_TRUE(d.true_parameters().has_value());
        EXPECT_EQ(*d.true_parameters(), e.truth);
    }
}

// README: on the clean `_tr` files the dynamic model recovers the truth to about 1e-4 relative
// (measured: Ld -9.1e-5 on the paper's motor, -1.3e-4 on the IPM motor, the others below 7e-5).
// The clean `_ss` files, near equilibrium at the end of long plateaus, satisfy the discrete
// equations almost exactly (measured: 8e-9 at most) and determine every parameter through the
// speed products, without a transient.
TEST(PmsmDynamicModel, RecoversTheTruthOnCleanFiles) {
    for (const std::string file :
         {"pmsm_public_2200rpm_2.5Nm_clean_tr.csv", "pmsm_public_ipm_1800rpm_4Nm_clean_tr.csv",
          "pmsm_public_2200rpm_2.5Nm_clean_ss.csv", "pmsm_public_ipm_1800rpm_4Nm_clean_ss.csv"}) {
        SCOPED_TRACE(file);
        const Dataset d = read(file);
        const LinearFit fit = fit_linear_model(dynamic_model({d}, {file}));
        const Eigen::Vector4d truth = *d.true_parameters();
        const double tolerance = file.find("_tr") != std::string::npos ? 2e-4 : 5e-8;
        for (Eigen::Index j = 0; j < 4; ++j)
            EXPECT_NEAR(fit.theta[j] / truth[j], 1.0, tolerance) << "parameter " << j;
        EXPECT_EQ(fit.rank, 4);
    }
}

// README: on the noisy files forward differences turn the in-loop current noise into a bias
// (here Rs +55 %, Ld -15 %). Smoothing before differencing removes most of it on the IPM motor
// (measured with K = 4: Rs +1.1 %, Ld +0.15 %, Lq -0.01 %, psi -0.07 %).
TEST(PmsmDynamicModel, SmoothingReducesTheNoiseBias) {
    const std::string file = "pmsm_public_ipm_1800rpm_4Nm_noisy_tr.csv";
    const Dataset d = read(file);
    const Eigen::Vector4d truth = *d.true_parameters();
    const LinearFit raw = fit_linear_model(dynamic_model({d}, {file}));
    EXPECT_GT(raw.theta[0] / truth[0], 1.4);
    const LinearFit smooth = fit_linear_model(dynamic_model({d}, {file}, {false, 4}));
    for (Eigen::Index j = 0; j < 4; ++j)
        EXPECT_NEAR(smooth.theta[j] / truth[j], 1.0, 0.02) << "parameter " << j;
}

// Data made to satisfy the discrete equations exactly (the voltage of row k computed from rows k
// and k + 1), with the dead-time term: the fit returns the parameters that made them.
TEST(PmsmDynamicModel, RecoversParametersOfExactDiscreteEquations) {
    const double rs = 0.9, ld = 6e-3, lq = 14e-3, psi = 0.17, vdt = 2.5;
    Rng rng(21);
    Dataset d;
    const int n = 200;
    std::vector<double> id(n), iq(n), w(n);
    for (int k = 0; k < n; ++k) {
        id[std::size_t(k)] = (k < n / 2 ? 0.5 : -2.0) + 0.3 * rng.normal(); // crosses zero: s_d changes sign
        iq[std::size_t(k)] = 8.0 + 0.5 * rng.normal();
        w[std::size_t(k)] = 560.0 + 2.0 * rng.normal();
    }
    for (std::size_t k = 0; k < std::size_t(n); ++k) {
        double ud = 0, uq = 0;
        if (k + 1 < std::size_t(n)) {
            const std::size_t j = k + 1;
            const double sd = 0.5 * (id[k] / std::hypot(id[k], iq[k]) + id[j] / std::hypot(id[j], iq[j]));
            const double sq = 0.5 * (iq[k] / std::hypot(id[k], iq[k]) + iq[j] / std::hypot(id[j], iq[j]));
            ud = rs * 0.5 * (id[k] + id[j]) + ld * (id[j] - id[k]) / Ts -
                 lq * 0.5 * (w[k] * iq[k] + w[j] * iq[j]) + vdt * sd;
            uq = rs * 0.5 * (iq[k] + iq[j]) + lq * (iq[j] - iq[k]) / Ts +
                 ld * 0.5 * (w[k] * id[k] + w[j] * id[j]) + psi * 0.5 * (w[k] + w[j]) + vdt * sq;
        }
        d.push_back(Ts * static_cast<double>(k), ud, uq, id[k], iq[k], w[k], false);
    }
    DynamicModelOptions options;
    options.fit_dead_time = true;
    const LinearModel model = dynamic_model({d}, {"exact.csv"}, options);
    EXPECT_EQ(model.parameter_names, (std::vector<std::string>{"Rs", "Ld", "Lq", "psi", "Vdt"}));
    const LinearFit fit = fit_linear_model(model);
    const double truth[] = {rs, ld, lq, psi, vdt};
    for (Eigen::Index j = 0; j < 5; ++j)
        EXPECT_NEAR(fit.theta[j] / truth[j], 1.0, 1e-10) << model.parameter_names[std::size_t(j)];
    EXPECT_LT(fit.f, 1e-18);
    // Without the fifth parameter the same data leave a residual.
    const LinearFit four = fit_linear_model(dynamic_model({d}, {"exact.csv"}));
    EXPECT_EQ(four.theta.size(), 4);
    EXPECT_GT(four.f, 0.1);
}

// One pair of rows by hand: the columns Rs Ld Lq psi, weight 0.25 as the factor 0.5 in A and b.
TEST(PmsmDynamicModel, EquationsOfOnePair) {
    Dataset d;
    d.push_back(0.0, 1.0, 2.0, -1.0, 3.0, 100.0, false);
    d.push_back(Ts, 5.0, 6.0, -2.0, 5.0, 110.0, false);
    const LinearModel model = dynamic_model({d}, {"pair.csv"});
    ASSERT_EQ(model.equations(), 2);
    EXPECT_EQ(model.d_rows, 1);
    EXPECT_EQ(model.run_starts, (std::vector<Eigen::Index>{0}));
    const double ts = sampling_period(d, "pair.csv");
    const Eigen::Vector4d d_row(0.5 * -1.5, 0.5 * -1.0 / ts, -0.5 * 0.5 * (300.0 + 550.0), 0.0);
    const Eigen::Vector4d q_row(0.5 * 4.0, 0.5 * 0.5 * (-100.0 - 220.0), 0.5 * 2.0 / ts, 0.5 * 105.0);
    for (Eigen::Index j = 0; j < 4; ++j) {
        EXPECT_DOUBLE_EQ(model.A(0, j), d_row[j]) << j;
        EXPECT_DOUBLE_EQ(model.A(1, j), q_row[j]) << j;
    }
    EXPECT_EQ(model.b[0], 0.5);
    EXPECT_EQ(model.b[1], 1.0);
}

// A dataset with time jumps: rows 0-4, an isolated row 5, rows 6-9. Equations pair (0,1)..(3,4)
// and (6,7)..(8,9) only; the id steps across the jumps are huge, so any equation formed across
// one would show in the derivative column.
TEST(PmsmDynamicModel, SegmentsNoEquationAcrossATimeJump) {
    Dataset d;
    const double times[] = {0, 1, 2, 3, 4, 10, 20, 21, 22, 23};
    const double currents[] = {0, 1, 2, 3, 4, 1000, -1000, -999, -998, -997};
    for (int k = 0; k < 10; ++k)
        d.push_back(Ts * times[k], 1.0, 2.0, currents[k], 5.0 + currents[k], 400.0, false);
    const double ts = sampling_period(d, "jumps.csv");
    EXPECT_NEAR(ts, Ts, 1e-15);
    const auto segments = contiguous_segments(d, ts);
    ASSERT_EQ(segments.size(), 3u);
    EXPECT_EQ(segments[1].size(), 1u);

    const LinearModel model = dynamic_model({d}, {"jumps.csv"});
    ASSERT_EQ(model.d_rows, 7);
    EXPECT_EQ(model.run_starts, (std::vector<Eigen::Index>{0, 4}));
    for (Eigen::Index e = 0; e < 7; ++e) {
        EXPECT_NEAR(model.A(e, 1), 0.5 * 1.0 / ts, 1e-9) << "d equation " << e;
        EXPECT_NEAR(model.A(7 + e, 2), 0.5 * 1.0 / ts, 1e-9) << "q equation " << e;
    }

    // Two datasets stacked: each dataset's segments start runs, offset by the first's equations.
    const LinearModel two = dynamic_model({d, d}, {"a.csv", "b.csv"});
    EXPECT_EQ(two.d_rows, 14);
    EXPECT_EQ(two.run_starts, (std::vector<Eigen::Index>{0, 4, 7, 11}));
    EXPECT_EQ(two.A.topRows(7), model.A.topRows(7));
    EXPECT_EQ(two.A.middleRows(7, 7), model.A.topRows(7));
    EXPECT_EQ(two.A.middleRows(14, 7), model.A.bottomRows(7));
}

// A centred moving average with K = 1 spreads a spike in ud at row 5 (of 11) over rows 4-6 as
// 1/3 each; at the segment ends the window shrinks to stay centred (row 0 is left alone).
// Signals linear in time pass any such filter unchanged.
TEST(PmsmDynamicModel, SmoothingIsACentredMovingAverageWithinSegments) {
    Dataset d;
    for (int k = 0; k < 11; ++k)
        d.push_back(Ts * k, k == 5 ? 3.0 : 0.0, k == 0 ? 6.0 : 0.0, 0.1 * k, 2.0 - 0.05 * k, 300.0 + k,
                    false);
    DynamicModelOptions options;
    options.smoothing = 1;
    const LinearModel raw = dynamic_model({d}, {"spike.csv"});
    const LinearModel smooth = dynamic_model({d}, {"spike.csv"}, options);
    ASSERT_EQ(smooth.d_rows, 10);
    for (Eigen::Index e = 0; e < 10; ++e) {
        EXPECT_NEAR(smooth.b[e], (e >= 4 && e <= 6) ? 0.5 * 1.0 : 0.0, 1e-15) << e;
        EXPECT_NEAR(smooth.b[10 + e], e == 0 ? 0.5 * 6.0 : (e == 1 ? 0.5 * 2.0 : 0.0), 1e-15) << e;
    }
    // Currents and speed linear in time: every column the same (the speed products are formed
    // from the smoothed signals, so they do not change either).
    for (Eigen::Index e = 0; e < 20; ++e)
        for (Eigen::Index j = 0; j < 4; ++j)
            EXPECT_NEAR(smooth.A(e, j), raw.A(e, j), 1e-9 * (1.0 + std::fabs(raw.A(e, j)))) << e << "," << j;
    options.smoothing = -1;
    EXPECT_THROW((void)dynamic_model({d}, {"spike.csv"}, options), std::invalid_argument);
}

TEST(PmsmDynamicModel, DeadTimeVoltageFromMetadata) {
    Dataset d;
    EXPECT_EQ(dead_time_voltage(d), 0.0);
    d.set_metadata("Vdc", 540.0);
    d.set_metadata("deadtime_s", 2e-6);
    EXPECT_EQ(dead_time_voltage(d), 0.0); // no Ts
    d.set_metadata("Ts", 1e-4);
    EXPECT_NEAR(dead_time_voltage(d), 4.0 / std::numbers::pi * 540.0 * 0.02, 1e-12);
    d.set_metadata("Ts", "fast");
    EXPECT_EQ(dead_time_voltage(d), 0.0);
    // The shared files have deadtime_s=0.
    EXPECT_EQ(dead_time_voltage(read("pmsm_public_2200rpm_2.5Nm_clean_tr.csv")), 0.0);
}

TEST(PmsmDynamicModel, ErrorsNameTheSource) {
    Dataset one;
    one.push_back(0.0, 1.0, 2.0, 0.0, 1.0, 100.0, false);
    try {
        (void)dynamic_model({one}, {"short.csv"});
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("short.csv"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)dynamic_model({}, {}), std::invalid_argument);
    EXPECT_THROW((void)dynamic_model({one}, {"a.csv", "b.csv"}), std::invalid_argument);
    Dataset bad;
    bad.push_back(0.0, 1.0, 2.0, 0.0, 1.0, 100.0, false);
    bad.push_back(Ts, 1.0, 2.0, std::nan(""), 1.0, 100.0, false);
    try {
        (void)dynamic_model({bad}, {"nan.csv"});
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("nan.csv: data row 0 "), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace mhb::pmsm
