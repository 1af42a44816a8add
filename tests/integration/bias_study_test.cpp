// The structural-bias audit end to end through the real binary: the bias preset with another
// optimiser list, few runs and a small budget; the console's verdict names each optimiser's
// verdict instead of a ranking; the report holds the structural_bias table, final_points.csv (one
// row per coordinate of each run's best point, as runs.csv has it) and its data dictionary.
#include <filesystem>

#include "cli_harness.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::lines_of;
using mhb::testing_cli::run_mhbench;
using mhb::testing_cli::shell_quoted;

TEST(BiasStudy, ThePresetTakesAnyOptimiserListAndReportsWhereTheFinalPointsLie) {
    const fs::path dir = mhb::testing_cli::fresh("bias_study");
    const auto run = run_mhbench("run --study bias --algorithms 'random-search tlbo' --runs 12 "
                                 "--budget evaluations=3000 --threads 2 --no-figures --out " +
                                 shell_quoted(dir));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("Structural bias on f0"), std::string::npos) << run.out;
    // Random search samples the box uniformly; TLBO's clamped moves pile its points on the bounds.
    EXPECT_NE(run.out.find("  Random search: no bias detected (KS 0/30, AD 0/30 dims;"), std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find("  TLBO: bounds ("), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("Per problem"), std::string::npos) << run.out; // no ranking on f0

    const fs::path report = dir / "report";
    const std::string table = mhb::testing_cli::read_text(report / "structural_bias.csv");
    EXPECT_EQ(lines_of(table).size(), 3u) << table;
    EXPECT_NE(table.find("Random search,12,30,0,0,"), std::string::npos) << table;
    const std::vector<std::string> points =
        lines_of(mhb::testing_cli::read_text(report / "final_points.csv"));
    ASSERT_EQ(points.size(), 1u + 2u * 12u * 30u);
    EXPECT_EQ(points.front(), "problem,algorithm,run,dimension,x");
    EXPECT_EQ(points[1].rfind("f0:dim=30,Random search,0,1,", 0), 0u) << points[1];
    EXPECT_NE(mhb::testing_cli::read_text(report / "README.md").find("### final_points.csv"),
              std::string::npos);
    // Every test behind the table's counts, a dimension a row, for a check by another implementation.
    const std::vector<std::string> tests =
        lines_of(mhb::testing_cli::read_text(report / "uniformity_tests.csv"));
    ASSERT_EQ(tests.size(), 1u + 2u * 30u);
    EXPECT_EQ(tests.front(),
              "problem,algorithm,runs,dimension,ks_statistic,ks_p,ks_holm_p,ad_statistic,ad_p,ad_holm_p");
    EXPECT_EQ(tests[1].rfind("f0:dim=30,Random search,12,1,", 0), 0u) << tests[1];
}

} // namespace
