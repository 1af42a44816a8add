// The console of `mhbench run` and `mhbench report` through the real binary: a verdict in one screen
// (at most 40 lines, none wider than 100 columns but those naming the study's paths) for the paper
// and the ablation presets (small), every table with --tables, nothing with -q; and the HTML pages
// of the ablation: index.html opens with the verdict and links a page per budget, each under 1 MB.
#include <algorithm>
#include <filesystem>

#include "cli_harness.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::lines_of;
using mhb::testing_cli::run_mhbench;
using mhb::testing_cli::shell_quoted;

// The widest line that does not name `dir` (a path is as long as the user made it).
std::size_t widest_line(const std::string& text, const fs::path& dir) {
    std::size_t widest = 0;
    for (const auto& line : lines_of(text))
        if (line.find(dir.string()) == std::string::npos)
            widest = std::max(widest, line.size());
    return widest;
}

TEST(VerdictConsole, TheAblationFitsOneScreenAndSaysWhatEachComponentDoes) {
    const fs::path dir = mhb::testing_cli::fresh("verdict_ablation");
    const auto run =
        run_mhbench("run --study ablation --runs 3 --budget iterations=10 --budget evaluations=800 "
                    "--threads 2 --no-figures --out " +
                    shell_quoted(dir));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_LE(lines_of(run.out).size(), 40u) << run.out;
    EXPECT_LE(widest_line(run.out, dir), 100u) << run.out;
    EXPECT_NE(run.out.find("Verdict, budget iterations=10 (alpha = 0.05):"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("Verdict, budget evaluations=800 (alpha = 0.05):"), std::string::npos);
    EXPECT_NE(run.out.find("Components of itlbo: obl x stepwise x tutorial (2^3), all problems (3)"),
              std::string::npos)
        << run.out;
    EXPECT_EQ(run.out.find("### Summary"), std::string::npos); // the tables stay in their files

    const auto tables = run_mhbench("report " + shell_quoted(dir) + " --no-figures --tables");
    ASSERT_EQ(tables.exit_code, 0) << tables.err;
    EXPECT_NE(tables.out.find("### Summary of final best-so-far values"), std::string::npos);
    EXPECT_NE(tables.out.find("Verdict, budget iterations=10"), std::string::npos);
    EXPECT_GT(lines_of(tables.out).size(), 200u);

    const auto quiet = run_mhbench("report " + shell_quoted(dir) + " --no-figures -q");
    ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
    EXPECT_EQ(quiet.out, "");

    // index.html: the verdict of both budgets and links to their pages, which hold the tables.
    const std::string index = mhb::testing_cli::read_text(dir / "report" / "index.html");
    EXPECT_LT(index.find("<section id=\"verdict\">"), index.find("<nav"));
    EXPECT_LT(index.find("<nav"), index.find("<section id=\"context\">"));
    for (const char* page : {"budget_iterations_10.html", "budget_evaluations_800.html"}) {
        EXPECT_NE(index.find(std::string("<a href=\"") + page + "\">"), std::string::npos) << page;
        ASSERT_TRUE(fs::exists(dir / "report" / page)) << page;
        EXPECT_LT(fs::file_size(dir / "report" / page), std::uintmax_t{1} << 20);
        EXPECT_NE(mhb::testing_cli::read_text(dir / "report" / page).find("Effect of each component"),
                  std::string::npos);
    }
    EXPECT_LT(fs::file_size(dir / "report" / "index.html"), std::uintmax_t{1} << 20);
}

TEST(VerdictConsole, ThePaperPresetRanksItsThreeAlgorithms) {
    const fs::path dir = mhb::testing_cli::fresh("verdict_paper");
    const auto run = run_mhbench(
        "run --study paper --runs 4 --iterations 20 --threads 2 --no-figures --out " + shell_quoted(dir));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_LE(lines_of(run.out).size(), 20u) << run.out;
    EXPECT_LE(widest_line(run.out, dir), 100u) << run.out;
    EXPECT_NE(
        run.out.find("pmsm:load=2,speed=2500 (4 runs; vs best: Wilcoxon signed-rank, paired runs, Holm)"),
        std::string::npos)
        << run.out;
    for (const char* rank : {"   1 ", "   2 ", "   3 "})
        EXPECT_NE(run.out.find(rank), std::string::npos) << rank;
    EXPECT_NE(run.out.find("best"), std::string::npos);
}

} // namespace
