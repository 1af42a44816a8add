// pdflatex on the LaTeX of real reports (issue 12): report.tex of the paper study and of an
// ablation with two budgets (run by the CLI with small presets), every table file included on its
// own, and the golden fixture of tests/data/latex/ compile without an error, without an Overfull
// \hbox (a table wider than the text) and without a float too large for the page. Skipped where
// pdflatex is not on PATH (scripts/latex-check.sh installs it).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "integration/cli_harness.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;
using mhb::test_support::read_text;
using mhb::testing_cli::run_mhbench;

bool have_pdflatex() {
    return std::system("command -v pdflatex >/dev/null 2>&1") == 0;
}

// What the log of the last pass says went wrong: errors, boxes too wide, floats too tall.
std::string problems_in_log(const fs::path& log) {
    std::istringstream in(read_text(log));
    std::string out;
    for (std::string line; std::getline(in, line);)
        if (line.rfind("!", 0) == 0 || line.find("Overfull \\hbox") != std::string::npos ||
            line.find("Float too large") != std::string::npos)
            out += line + "\n";
    return out;
}

// Compiles `file` (in `dir`) twice, as one does for references and longtable widths; returns what
// went wrong ("" when nothing did).
std::string compile(const fs::path& dir, const std::string& file) {
    const std::string command = "cd '" + dir.string() +
                                "' && pdflatex -interaction=nonstopmode -halt-on-error '" + file +
                                "' >/dev/null 2>&1";
    const int first = std::system(command.c_str());
    const int second = first == 0 ? std::system(command.c_str()) : first;
    const fs::path log = dir / (fs::path(file).stem().string() + ".log");
    std::string problems = problems_in_log(log);
    if (second != 0 && problems.empty())
        problems = "pdflatex failed (see " + log.string() + ")\n";
    return problems;
}

// A document that \input's every table file of `report` on its own: each stands alone with the
// packages its first comment names.
std::string standalone_tables(const fs::path& report) {
    std::string inputs;
    for (const auto& entry : fs::directory_iterator(report))
        if (entry.path().extension() == ".tex" && entry.path().filename() != "report.tex" &&
            entry.path().filename() != "tables.tex")
            inputs += "\\input{" + entry.path().filename().string() + "}\n\\clearpage\n";
    std::ofstream(report / "tables.tex")
        << "\\documentclass{article}\n\\usepackage[T1]{fontenc}\n"
           "\\usepackage{lmodern}\n\\usepackage{booktabs,array,longtable,graphicx}\n"
           "\\begin{document}\n"
        << inputs << "\\end{document}\n";
    return compile(report, "tables.tex");
}

fs::path run_study(const std::string& name, const std::string& run_args) {
    const fs::path dir = mhb::test_support::fresh_temporary_path("mhb_latex_", name);
    const auto run = run_mhbench("run " + run_args + " --no-report -q --out '" + dir.string() + "'");
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const auto report = run_mhbench("report '" + dir.string() + "' --no-figures --format tex");
    EXPECT_EQ(report.exit_code, 0) << report.err;
    return dir / "report";
}

TEST(LatexReport, PaperStudyCompilesAndEveryTableFits) {
    if (!have_pdflatex())
        GTEST_SKIP() << "no pdflatex on PATH (scripts/latex-check.sh installs TeX Live)";
    const fs::path report = run_study("paper", "--study paper --runs 3");
    EXPECT_EQ(compile(report, "report.tex"), "");
    EXPECT_EQ(standalone_tables(report), "");
}

TEST(LatexReport, AblationWithTwoBudgetsCompilesAndEveryTableFits) {
    if (!have_pdflatex())
        GTEST_SKIP() << "no pdflatex on PATH (scripts/latex-check.sh installs TeX Live)";
    const fs::path report =
        run_study("ablation", "--study ablation --runs 2 --budget iterations=8 --budget evaluations=1500");
    EXPECT_NE(read_text(report / "report.tex").find("\\section{Budget evaluations=1500}"), std::string::npos);
    EXPECT_EQ(compile(report, "report.tex"), "");
    EXPECT_EQ(standalone_tables(report / "iterations_8"), "");
}

TEST(LatexReport, GoldenFixtureCompiles) {
    if (!have_pdflatex())
        GTEST_SKIP() << "no pdflatex on PATH (scripts/latex-check.sh installs TeX Live)";
    const fs::path dir = mhb::test_support::fresh_temporary_path("mhb_latex_", "golden");
    fs::create_directories(dir);
    fs::copy_file(fs::path(MHB_TEST_DATA_DIR) / "latex" / "report.tex", dir / "report.tex");
    EXPECT_EQ(compile(dir, "report.tex"), "");
}

} // namespace
} // namespace mhb
