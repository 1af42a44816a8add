// The `fluxmap` problem end to end: `mhbench eval` prints the objective that the papers' formulas
// give (computed here point by point with std::pow, sharing no code with problems/fluxmap), on the
// shipped map and on a user's file, and `mhbench plugin-check` finds the family fit for a study.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.hpp"
#include "problems/core/parameters.hpp"

namespace mhb {
namespace {

using namespace mhb::testing_cli;

struct FluxCliPoint {
    double i_d, i_q, psi_d, psi_q;
};

std::vector<FluxCliPoint> flux_cli_points(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    std::vector<FluxCliPoint> points;
    for (FluxCliPoint p{}; std::getline(in, line);) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream(line) >> p.i_d >> p.i_q >> p.psi_d >> p.psi_q;
        points.push_back(p);
    }
    return points;
}

// PM-SyRM (Lelli et al. 2024) written out: sum of squared current errors, A^2.
double flux_cli_objective(const std::vector<FluxCliPoint>& points, const std::vector<double>& t) {
    double sum = 0;
    for (const FluxCliPoint& p : points) {
        const double d = std::fabs(p.psi_d), q = std::fabs(p.psi_q);
        const double g_d =
            t[0] + t[1] * std::pow(d, t[5]) + t[4] / (t[8] + 2) * std::pow(d, t[7]) * std::pow(q, t[8] + 2);
        const double g_q =
            t[2] + t[3] * std::pow(q, t[6]) + t[4] / (t[7] + 2) * std::pow(d, t[7] + 2) * std::pow(q, t[8]);
        const double psi_b = p.psi_d - t[9];
        const double s = std::sqrt(psi_b * psi_b + t[13] * p.psi_q * p.psi_q);
        const double g_b = t[10] * std::pow(s, t[12]) / (1 + t[11] * std::pow(s, t[12]));
        const double e_d = g_d * p.psi_d + g_b * psi_b - p.i_d;
        const double e_q = g_q * p.psi_q + t[13] * g_b * p.psi_q - p.i_q;
        sum += e_d * e_d + e_q * e_q;
    }
    return sum;
}

const std::vector<double> flux_cli_theta = {3.1, 25.0, 6.2,  3.3,  38.0, 4.3, 5.7,
                                            0.8, 1.3,  0.77, 90.0, 1.4,  2.6, 0.15};

double eval_at_theta(const std::string& problem) {
    const auto points = fresh("fluxmap_theta.txt");
    std::ofstream out(points);
    out.precision(17);
    for (double v : flux_cli_theta)
        out << v << ' ';
    out << '\n';
    out.close();
    const CliResult r = run_mhbench("eval --problem " + problem + " --points " + shell_quoted(points));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    double f = 0;
    EXPECT_TRUE(parse_real(lines_of(r.out).at(0), f)) << r.out;
    return f;
}

TEST(FluxMapCli, EvalGivesThePapersValueOnTheShippedMap) {
    const auto points = flux_cli_points(std::string(MHB_SOURCE_DIR) +
                                        "/problems/fluxmap/data/baldor-ecs101m0h7ef4-400rpm.csv");
    ASSERT_EQ(points.size(), 567u);
    const double want = flux_cli_objective(points, flux_cli_theta);
    EXPECT_NEAR(eval_at_theta("fluxmap:model=pmsyrm"), want, 1e-12 * want);
}

TEST(FluxMapCli, EvalGivesThePapersValueOnAUsersFile) {
    const auto file = fresh("fluxmap_user.csv");
    std::ofstream out(file);
    out.precision(17);
    out << "psi_d,psi_q,i_d,i_q\n"; // any column order
    for (int k = 0; k < 20; ++k)
        out << 0.1 + 0.04 * k << ',' << -0.9 + 0.09 * k << ',' << -10 + k << ',' << 3 - 0.5 * k << '\n';
    out.close();
    std::vector<FluxCliPoint> points;
    for (int k = 0; k < 20; ++k)
        points.push_back({-10.0 + k, 3 - 0.5 * k, 0.1 + 0.04 * k, -0.9 + 0.09 * k});
    const double want = flux_cli_objective(points, flux_cli_theta);
    EXPECT_NEAR(eval_at_theta("fluxmap:model=pmsyrm,data=" + shell_quoted(file)), want, 1e-12 * want);
}

TEST(FluxMapCli, PluginCheckPasses) {
    for (const char* spec : {"fluxmap", "fluxmap:model=syrm", "fluxmap:synthetic=on,noise=0.05"}) {
        const CliResult r = run_mhbench(std::string("plugin-check --problem ") + spec);
        EXPECT_EQ(r.exit_code, 0) << spec << "\n" << r.out << r.err;
        EXPECT_NE(r.out.find("verdict: pass"), std::string::npos) << spec << "\n" << r.out;
    }
}

// `identify --flux-map`: the same report at any thread count, the shipped optimum re-found, a
// verdict per parameter, and a user's file with its columns in another order fitted the same.
TEST(FluxMapCli, IdentifyFindsTheShippedOptimumAtAnyThreadCount) {
    const CliResult one = run_mhbench("identify --flux-map shipped --starts 3 --threads 1");
    const CliResult two = run_mhbench("identify --flux-map shipped --starts 3 --threads 2");
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_EQ(one.out, two.out);
    EXPECT_NE(one.out.find("fit:  f = 36.0995588759 A^2"), std::string::npos) << one.out;
    EXPECT_NE(one.out.find("3 of 3 starts reached it"), std::string::npos) << one.out;
    int verdicts = 0;
    for (const std::string& line : lines_of(one.out))
        verdicts += line.rfind("  ", 0) == 0 && line.find(" determined (") != std::string::npos ? 1 : 0;
    EXPECT_EQ(verdicts, 14) << one.out;
}

TEST(FluxMapCli, IdentifyWritesItsNumbersAndTheyAgreeWithTheReport) {
    const auto shipped = flux_cli_points(std::string(MHB_SOURCE_DIR) +
                                         "/problems/fluxmap/data/baldor-ecs101m0h7ef4-400rpm.csv");
    const auto file = fresh("fluxmap_identify.csv");
    std::ofstream out(file);
    out.precision(17);
    out << "psi_q,psi_d,i_q,i_d\n";
    for (const FluxCliPoint& p : shipped)
        out << p.psi_q << ',' << p.psi_d << ',' << p.i_q << ',' << p.i_d << '\n';
    out.close();
    const auto dir = fresh("fluxmap_identify_out");
    const CliResult r = run_mhbench("identify --flux-map " + shell_quoted(file) +
                                    " --model syrm --starts 2 --out " + shell_quoted(dir));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("SyRM current map (Hinkkanen et al. 2017, 9 parameters)"), std::string::npos)
        << r.out;
    const auto estimates = lines_of(run_shell("cat " + shell_quoted(dir / "estimates.csv")).out);
    ASSERT_EQ(estimates.size(), 10u);
    EXPECT_EQ(estimates[0],
              "parameter,estimate,standard_error,relative_error,spread_over_starts,verdict,lower,upper");
    EXPECT_EQ(estimates[1].substr(0, 5), "a_d0,");
    // points.csv: every point with the model's currents; its errors add up to the printed f.
    std::ifstream points(dir / "points.csv");
    std::string line;
    std::getline(points, line);
    EXPECT_EQ(line, "i_d,i_q,psi_d,psi_q,i_d_model,i_q_model,error_d,error_q");
    double f = 0;
    int rows = 0;
    for (; std::getline(points, line); ++rows) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream cells(line);
        std::vector<double> v(8);
        for (double& x : v)
            cells >> x;
        f += v[6] * v[6] + v[7] * v[7];
    }
    EXPECT_EQ(rows, 567);
    const auto at = r.out.find("fit:  f = ");
    ASSERT_NE(at, std::string::npos);
    EXPECT_NEAR(std::stod(r.out.substr(at + 10)), f, 1e-9 * f);
    EXPECT_EQ(lines_of(run_shell("cat " + shell_quoted(dir / "curves.csv")).out).size(), 1u + 10u * 121u);
    if (r.out.find("figure: ") != std::string::npos) { // drawn when a Python with matplotlib is found
        EXPECT_TRUE(std::filesystem::exists(dir / "flux-map.pdf"));
        EXPECT_TRUE(std::filesystem::exists(dir / "flux-map.png"));
        EXPECT_FALSE(
            std::filesystem::exists(dir / "flux-map.svg")); // PDF and PNG as plot_study.py's (issue 37)
    }
}

} // namespace
} // namespace mhb
