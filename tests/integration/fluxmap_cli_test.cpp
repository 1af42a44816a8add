// The `fluxmap` problem end to end: `mhbench eval` prints the objective that the papers' formulas
// give (computed here point by point with std::pow, sharing no code with problems/fluxmap), on the
// shipped map and on a user's file, and `mhbench plugin-check` finds the family fit for a study.
#include <algorithm>
#include <cmath>
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

} // namespace
} // namespace mhb
