// The LaTeX of a report (issue 12): every .tex file of a fixed study built in memory matches its
// golden copy in tests/data/latex/ (regenerate with MHB_UPDATE_GOLDEN=1 after a deliberate change,
// compile tests/data/latex/report.tex and review the PDF and the diff), and the layout rules hold on
// tables made for them: one numbering, wide tables split with their key columns repeated, constant
// columns said once, long tables continued in floats that fit a page. The latex-labelled test
// (tests/latex/) compiles real reports with pdflatex.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>

#include "results/latex/latex_table.hpp"
#include "results/latex/latex_text.hpp"
#include "results/report/report.hpp"
#include "results/table_model/table.hpp"
#include "support/files.hpp"
#include "support/text.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;
using mhb::test_support::read_text;

using mhb::test_support::count;

// Four algorithms (itlbo and itlbo:obl=off form a 2^1 on/off design) on a PMSM problem and a
// sphere, six paired runs each, at two budgets; one run of pso ends at +inf on the sphere.
StudyData latex_study() {
    StudyData data;
    data.directory = "/nonexistent/latex_study";
    data.context_text = "# where and how\nversion = 0.1.0\ncommand = mhbench run --study x --out y\n";
    data.algorithms = {{"itlbo", "itlbo", "itlbo:np=50,obl=on,tutorial=on"},
                       {"itlbo:obl=off", "itlbo[O-]", "itlbo:np=50,obl=off,tutorial=on"},
                       {"tlbo", "tlbo", "tlbo:np=50"},
                       {"pso", "pso", "pso:c1=2,c2=2,np=50,w=0.5"}};
    const double pmsm_gap[] = {0.12, 0.5, 1.5, 2.2};
    std::int64_t id = 0;
    for (const std::string budget : {"iterations=2", "evaluations=300"})
        for (const std::string problem : {"pmsm:load=2,speed=2500", "sphere:dim=2"})
            for (std::size_t a = 0; a < data.algorithms.size(); ++a)
                for (std::int64_t i = 0; i < 6; ++i) {
                    RunRecord r;
                    r.run_id = id++;
                    r.algorithm = data.algorithms[a].spec;
                    r.problem = problem;
                    r.budget = budget;
                    r.run_index = i;
                    r.seed = 100 + static_cast<std::uint64_t>(i);
                    const double spread = 1.0 + 0.1 * static_cast<double>(i) * static_cast<double>(a + 1);
                    const double scale = budget == "iterations=2" ? 1.0 : 0.5;
                    r.evaluations = budget == "iterations=2" ? 150 * static_cast<std::int64_t>(a + 1) : 300;
                    r.iterations = 2;
                    if (problem == "sphere:dim=2") {
                        r.f_opt = 0.0;
                        r.best_f = scale * std::pow(10.0, -2.0 - 2.0 * static_cast<double>(a)) * spread;
                        if (a == 3 && i == 5)
                            r.best_f = std::numeric_limits<double>::infinity(); // legal: the worst
                        r.best_x = {0.01, -0.02};
                    } else {
                        r.f_opt = 3.9;
                        r.best_f = 3.9 + scale * pmsm_gap[a] * spread;
                        r.parameter_names = {"Rs", "Ld", "Lq", "psi"};
                        r.true_parameters = {0.330, 0.00324, 0.00324, 0.0776};
                        r.x_opt = {0.331, 0.003245, 0.003238, 0.07762};
                        const double d = 0.001 * static_cast<double>(a + 1) * spread;
                        r.best_x = {0.33 + d, 0.00324 * (1 + d), 0.00324 - 1e-3 * d, 0.0776 + 0.01 * d};
                    }
                    const double f = r.best_f;
                    r.checkpoints = {{1, 8 * f}, {10, 4 * f}, {100, 2 * f}, {r.evaluations, f}};
                    r.curve = {{0, r.evaluations / 2, 2 * f, {}}, {1, r.evaluations, f, {}}};
                    data.runs.push_back(r);
                }
    return data;
}

TEST(LatexGolden, EveryTexFileOfTheReportMatchesItsGoldenCopy) {
    const fs::path out = mhb::test_support::fresh_temporary_path("mhb_latex_golden_", "report");
    ReportOptions options;
    options.out_dir = out;
    options.figures = false;
    options.formats = {"tex"};
    std::ostringstream console;
    build_report(latex_study(), options, console);
    const fs::path golden = fs::path(MHB_TEST_DATA_DIR) / "latex";
    const bool update = std::getenv("MHB_UPDATE_GOLDEN") != nullptr;
    std::size_t compared = 0;
    for (const auto& entry : fs::recursive_directory_iterator(out)) {
        if (!entry.is_regular_file() || entry.path().extension() != ".tex")
            continue;
        const fs::path relative = fs::relative(entry.path(), out);
        if (update) {
            fs::create_directories((golden / relative).parent_path());
            fs::copy_file(entry.path(), golden / relative, fs::copy_options::overwrite_existing);
        }
        ASSERT_TRUE(fs::exists(golden / relative))
            << relative << " has no golden copy (MHB_UPDATE_GOLDEN=1 makes it)";
        EXPECT_EQ(read_text(entry.path()), read_text(golden / relative))
            << relative << " differs from its golden copy";
        ++compared;
    }
    EXPECT_EQ(compared,
              25u); // report.tex, eleven tables (ecdf_area and ert among them) and methods.tex per budget
    const std::string report = read_text(out / "report.tex");
    EXPECT_NE(report.find("\\section{Budget evaluations=300}"), std::string::npos);
    EXPECT_NE(report.find("\\usepackage[T1]{fontenc}"), std::string::npos);
    EXPECT_NE(report.find("\\texttt{/\\allowbreak{}nonexistent/\\allowbreak{}latex\\_study}"),
              std::string::npos);
    EXPECT_EQ(report.find("\\caption{Table"), std::string::npos); // LaTeX numbers the tables itself
    // No protocol: the study's own PMSM tables, named by the condition, not by the spec.
    EXPECT_NE(report.find("\\caption{Fitness of each algorithm (PMSM, 2500 rpm, 2 N m)}"), std::string::npos);
    EXPECT_EQ(report.find("Table 2"), std::string::npos);
    EXPECT_NE(report.find("$\\infty$"), std::string::npos); // the +inf run, as maths
}

// "v" and the column's number, appended: `"v" + std::to_string(c)` makes GCC 12 warn falsely
// (-Wstringop-overflow) once inlined into a unity batch.
std::string column_name(std::size_t c) {
    std::string name = "v";
    name += std::to_string(c);
    return name;
}

Table wide_table(std::size_t rows, std::size_t columns) {
    Table t;
    t.id = "wide";
    t.title = "Table 9: A wide table [budget iterations=2]";
    t.caption = "Values of p and A12 against f*. Budget: iterations=2.";
    t.header = {"Problem", "Algorithm"};
    for (std::size_t c = 0; c < columns; ++c)
        t.header.push_back(column_name(c));
    for (std::size_t r = 0; r < rows; ++r) {
        std::vector<TableCell> row = {text_cell("sphere:dim=2"), text_cell("algorithm" + std::to_string(r))};
        for (std::size_t c = 0; c < columns; ++c)
            row.push_back(
                number_cell(std::pow(10.0, -static_cast<double>(c)) * (1.0 + static_cast<double>(r)), 4));
        t.add_row(std::move(row));
    }
    t.latex_column(0).fold_constant = true;
    t.latex_column(1).key = true;
    for (std::size_t c = 0; c < columns; ++c)
        t.latex_column(2 + c).group = c < columns / 2 ? "first half" : "second half";
    format_columns(t);
    return t;
}

TEST(LatexLayout, OneNumberingAndWhatEveryRowSharesSaidOnce) {
    const std::string latex = render_latex(wide_table(3, 2));
    EXPECT_NE(latex.find("\\caption{A wide table}"), std::string::npos) << latex; // no "Table 9:", no budget
    EXPECT_NE(latex.find("Problem: sphere:\\allowbreak{}dim=2. Values of $p$ and $A_{12}$ against $f^*$."),
              std::string::npos)
        << latex;
    EXPECT_EQ(latex.find("& sphere"), std::string::npos) << latex; // no Problem column left
    EXPECT_EQ(count(latex, "\\begin{table}"), 1u) << latex;        // narrow: one IEEE column
}

TEST(LatexLayout, AWideTableIsSplitWithItsKeyColumnsRepeated) {
    const std::string latex = render_latex(wide_table(3, 12));
    const std::size_t parts = count(latex, "\\begin{table");
    EXPECT_GE(parts, 2u) << latex;
    EXPECT_EQ(count(latex, "algorithm0 &"), parts) << latex; // the key column in every part
    EXPECT_NE(latex.find("(first half; part 1 of " + std::to_string(parts) + ")"), std::string::npos)
        << latex;
    EXPECT_NE(latex.find("Notes as for Table~\\ref{tab:wide}."), std::string::npos);
    EXPECT_EQ(count(latex, "Values of $p$"), 1u); // the notes once, under the first part
    for (std::size_t c = 0; c < 12; ++c)          // every column is in some part, once
        EXPECT_EQ(count(latex, column_name(c) + " &") + count(latex, column_name(c) + " \\\\"), 1u) << c;
}

// The floats a table was split into: the text of each, from its \begin{table to its \end{table.
std::vector<std::string> floats_of(const std::string& latex) {
    std::vector<std::string> out;
    for (std::size_t at = latex.find("\\begin{table"); at != std::string::npos;
         at = latex.find("\\begin{table", at + 1))
        out.push_back(latex.substr(at, latex.find("\\end{table", at) - at));
    return out;
}

TEST(LatexLayout, ALongTableContinuesInFloatsThatFitAPage) {
    const std::string latex = render_latex(wide_table(120, 2));
    EXPECT_EQ(latex.find("longtable"), std::string::npos) << latex; // refused by two-column classes
    const auto floats = floats_of(latex);
    ASSERT_GE(floats.size(), 3u) << latex; // 120 lines of 9.8 pt: more than two pages of 528 pt
    EXPECT_EQ(count(latex, "\\label{"), 1u) << latex;
    EXPECT_NE(floats.front().find("\\caption{A wide table}\n\\label{tab:wide}"), std::string::npos);
    EXPECT_EQ(count(latex, "Values of $p$"), 1u); // the notes once, under the first float
    std::size_t rows = 0;
    for (std::size_t f = 0; f < floats.size(); ++f) {
        EXPECT_EQ(count(floats[f], "\\toprule\nAlgorithm & v0 & v1 \\\\\n\\midrule"), 1u)
            << floats[f]; // the header
        if (f > 0) {
            EXPECT_NE(floats[f].find("\\addtocounter{table}{-1}\n\\caption{A wide table (continued)}"),
                      std::string::npos)
                << floats[f];
        }
        const std::size_t here = count(floats[f], "\\\\\n") - 1;
        EXPECT_LE(static_cast<double>(here) * 9.8, 0.96 * 550 - 50) << floats[f]; // less caption and header
        rows += here;
    }
    EXPECT_EQ(rows, 120u);
    for (std::size_t r = 0; r < 120; ++r) // every row once, in order
        EXPECT_EQ(count(latex, "algorithm" + std::to_string(r) + " &"), 1u) << r;
    EXPECT_LT(latex.find("algorithm118 &"), latex.find("algorithm119 &"));
}

// Ten problems heading runs of eight algorithms each (ITLBO's ablation variants, say).
Table headed_table(std::size_t problems, std::size_t algorithms) {
    Table t;
    t.id = "headed";
    t.title = "Table 3: Variants by problem";
    t.caption = "Median (IQR) of the final fitness.";
    t.header = {"Problem", "Algorithm", "Median"};
    for (std::size_t p = 0; p < problems; ++p)
        for (std::size_t a = 0; a < algorithms; ++a)
            t.add_row(
                {text_cell("pmsm:load=" + std::to_string(p)), text_cell("variant" + std::to_string(a)),
                 spread_cell(1.0 + static_cast<double>(a), 0.1, a % 2 == 0 ? "+" : "-", {4, -1}, {2, -1})});
    t.latex_column(0).heading = true;
    t.latex_column(1).key = true;
    format_columns(t);
    return t;
}

TEST(LatexLayout, ALongTableBreaksBetweenRunsOfRowsUnderAHeading) {
    const std::string latex = render_latex(headed_table(10, 8));
    const auto floats = floats_of(latex);
    ASSERT_GE(floats.size(), 2u) << latex;
    for (const auto& f : floats) {
        // Each float starts with a heading and never ends with one.
        EXPECT_NE(f.find("\\midrule\n\\multicolumn{2}{l}{\\textit{pmsm:"), std::string::npos) << f;
        EXPECT_EQ(f.find("}} \\\\\n\\bottomrule"), std::string::npos) << f;
        EXPECT_EQ(count(f, "variant0 &"), count(f, "variant7 &")) << f; // runs kept whole
    }
    EXPECT_EQ(count(latex, "\\textit{pmsm:"), 10u) << latex; // no heading repeated
}

TEST(LatexLayout, ARunLongerThanAPageContinuesUnderItsHeadingAgain) {
    const std::string latex = render_latex(headed_table(1, 80));
    const auto floats = floats_of(latex);
    ASSERT_GE(floats.size(), 2u) << latex;
    for (const auto& f : floats)
        EXPECT_NE(f.find("\\midrule\n\\multicolumn{2}{l}{\\textit{pmsm:"), std::string::npos) << f;
}

TEST(LatexText, MathsForSymbolsAndMinusSigns) {
    EXPECT_EQ(latex_prose("Mean gap f - f*"), "Mean gap $f - f^*$");
    EXPECT_EQ(latex_prose("p (Holm), A12 and theta*"), "$p$ (Holm), $A_{12}$ and $\\theta^*$");
    EXPECT_EQ(latex_prose("interaction -4.57: obl helps"), "interaction $-4.57$: obl helps");
    EXPECT_EQ(latex_prose("floor = 1e-300, paired"), "floor $=$ $1\\times10^{-300}$, paired");
    EXPECT_EQ(latex_prose("+ better, - worse, = same"), "$+$ better, $-$ worse, $=$ same");
    EXPECT_EQ(latex_spec_text("pmsm:load=2,speed=2500"),
              "pmsm:\\allowbreak{}load=2,\\allowbreak{}speed=2500");
    EXPECT_EQ(latex_escape("--study 50% a_b"), "-{}-study 50\\% a\\_b"); // no en dash
}

} // namespace
} // namespace mhb
