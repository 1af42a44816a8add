// pdflatex on the LaTeX of real reports (issue 12): report.tex of the paper study and of an
// ablation with two budgets (run by the CLI with small presets), every table file included on its
// own, and the golden fixture of tests/data/latex/ compile without an error, without an Overfull
// \hbox (a table wider than the text) and without a float too large for the page. The tables of
// an ablation (8 variants x 3 conditions: tables long enough to be split into several floats) do
// the same in two-column journals, IEEEtran's conference layout and elsarticle's 5p (issue 21).
// Skipped where pdflatex, or the journal's class, is missing (scripts/latex-check.sh installs them).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

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

// A class file TeX finds (IEEEtran.cls and elsarticle.cls come with Debian's texlive-publishers).
bool have_tex_file(const std::string& file) {
    return std::system(("kpsewhich '" + file + "' >/dev/null 2>&1").c_str()) == 0;
}

// What the log of the last pass says went wrong: errors, boxes too wide, floats too tall.
std::string problems_in_log(const fs::path& log) {
    std::istringstream in(read_text(log));
    std::string out;
    for (std::string line; std::getline(in, line);)
        if (line.rfind('!', 0) == 0 || line.find("Overfull \\hbox") != std::string::npos ||
            line.find("Float too large") != std::string::npos)
            out += line + "\n";
    return out;
}

// Compiles `file` (in `dir`) twice, as one does for references; returns what went wrong ("" when
// nothing did).
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

// A document `name`.tex of class `document_class` (with its options) that \input's every table
// file of `report` on its own, with `preamble` and the packages the files' "% Needs \usepackage{...}."
// comments name.
std::string tables_in(const fs::path& report, const std::string& name, const std::string& document_class,
                      const std::string& preamble = "") {
    static const std::string needs = "% Needs \\usepackage{";
    std::string inputs;
    std::string packages;
    for (const auto& entry : fs::directory_iterator(report)) {
        const std::string file = entry.path().filename().string();
        if (entry.path().extension() != ".tex" || file == "report.tex" || file.rfind("tables", 0) == 0)
            continue;
        inputs += "\\input{" + file + "}\n\\clearpage\n";
        const std::string text = read_text(entry.path());
        for (std::size_t at = text.find(needs); at != std::string::npos; at = text.find(needs, at + 1)) {
            const std::size_t begin = at + needs.size();
            std::istringstream list(text.substr(begin, text.find('}', begin) - begin));
            for (std::string package; std::getline(list, package, ',');)
                if (("," + packages + ",").find("," + package + ",") == std::string::npos)
                    packages += (packages.empty() ? "" : ",") + package;
        }
    }
    EXPECT_FALSE(inputs.empty()) << "no table file in " << report;
    std::ofstream(report / (name + ".tex"))
        << "\\documentclass" << document_class << "\n"
        << preamble << "\\usepackage{" << packages << "}\n\\begin{document}\n"
        << inputs << "\\end{document}\n";
    return compile(report, name + ".tex");
}

// Every table file of `report` in a one-column article, each on its own.
std::string standalone_tables(const fs::path& report) {
    return tables_in(report, "tables", "{article}", "\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n");
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

// The report of an ablation at one small budget: ITLBO's 8 component variants on the preset's 3
// conditions, so that the tables of variants by conditions are split into floats.
fs::path ablation_report(const std::string& name) {
    const fs::path report = run_study(name, "--study ablation --runs 2 --budget iterations=4");
    bool continued = false;
    for (const auto& entry : fs::directory_iterator(report))
        if (entry.path().extension() == ".tex" && entry.path().filename() != "report.tex")
            continued = continued || read_text(entry.path()).find("(continued)}") != std::string::npos;
    EXPECT_TRUE(continued) << "no table of " << report << " is long enough to be continued";
    return report;
}

TEST(LatexReport, AblationTablesFitTwoColumnIeeeConferencePages) {
    if (!have_pdflatex() || !have_tex_file("IEEEtran.cls"))
        GTEST_SKIP() << "no pdflatex or no IEEEtran.cls (scripts/latex-check.sh installs texlive-publishers)";
    const fs::path report = ablation_report("ieee");
    EXPECT_EQ(tables_in(report, "tables_ieee", "[conference]{IEEEtran}"), "");
}

TEST(LatexReport, AblationTablesFitTwoColumnElsevierPages) {
    if (!have_pdflatex() || !have_tex_file("elsarticle.cls"))
        GTEST_SKIP()
            << "no pdflatex or no elsarticle.cls (scripts/latex-check.sh installs texlive-publishers)";
    const fs::path report = ablation_report("elsevier");
    EXPECT_EQ(tables_in(report, "tables_elsevier", "[5p]{elsarticle}"), "");
}

// The ```latex blocks of README.md's section "## Tables in your paper", in order.
std::vector<std::string> readme_latex_blocks() {
    const std::string readme = read_text(fs::path(MHB_SOURCE_DIR) / "README.md");
    const std::size_t begin = readme.find("\n## Tables in your paper\n");
    EXPECT_NE(begin, std::string::npos) << "README.md has no section \"Tables in your paper\"";
    if (begin == std::string::npos)
        return {};
    const std::size_t end = std::min(readme.find("\n## ", begin + 1), readme.size());
    const std::string section = readme.substr(begin, end - begin);
    std::vector<std::string> blocks;
    static const std::string open = "```latex\n";
    for (std::size_t at = section.find(open); at != std::string::npos; at = section.find(open, at + 1)) {
        const std::size_t from = at + open.size();
        blocks.push_back(section.substr(from, section.find("```", from) - from));
    }
    return blocks;
}

// The floats of a .tex file that name fewer than two of `labels` (a float holding one algorithm).
std::string floats_with_one_algorithm(const std::string& tex, const std::vector<std::string>& labels) {
    std::string out;
    for (std::size_t at = tex.find("\\begin{table"); at != std::string::npos;
         at = tex.find("\\begin{table", at + 1)) {
        std::string body = tex.substr(at, tex.find("\\end{table", at) - at);
        std::size_t named = 0;
        for (const auto& label : labels) // longest first: ITLBO before TLBO
            if (const std::size_t found = body.find(label); found != std::string::npos) {
                ++named;
                for (std::size_t k = body.find(label); k != std::string::npos; k = body.find(label))
                    body.replace(k, label.size(), "");
            }
        if (named < 2)
            out += tex.substr(at, 200) + "\n...\n";
    }
    return out;
}

// README.md's documents for IEEEtran and elsarticle compile with the tables of a real report: five
// algorithms with their default labels (an NLopt and a CMA-ES spec among them) on one PMSM problem;
// and no float of those tables holds one algorithm (issue 37).
TEST(LatexReport, ReadmeDocumentsCompileWithAPmsmStudysTables) {
    if (!have_pdflatex() || !have_tex_file("IEEEtran.cls") || !have_tex_file("elsarticle.cls"))
        GTEST_SKIP() << "no pdflatex, IEEEtran.cls or elsarticle.cls (scripts/latex-check.sh installs them)";
    const std::vector<std::string> blocks = readme_latex_blocks();
    ASSERT_EQ(blocks.size(), 2u);
    EXPECT_NE(blocks[0].find("{IEEEtran}"), std::string::npos);
    EXPECT_NE(blocks[1].find("{elsarticle}"), std::string::npos);
    const fs::path report =
        run_study("readme", "--algorithms 'itlbo tlbo pso nlopt:algorithm=LN_BOBYQA cmaes' "
                            "--problems pmsm:speed=2500,load=2 --runs 5 --iterations 30");
    const fs::path study = report.parent_path();
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const std::string name = "paper_" + std::to_string(i) + ".tex";
        std::ofstream(study / name) << blocks[i];
        EXPECT_EQ(compile(study, name), "") << blocks[i];
    }
    const std::vector<std::string> labels = {"CMA-ES (IPOP)", "BOBYQA", "ITLBO", "TLBO", "PSO"};
    for (const char* table : {"fitness", "parameters", "summary", "comparison", "tests"})
        EXPECT_EQ(floats_with_one_algorithm(read_text(report / (std::string(table) + ".tex")), labels), "")
            << table;
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
