// Reporters (results/reporters/): every output of a report is a reporter registered by name. A
// format added here, in the test alone (reStructuredText tables), is chosen with --format and
// written by build_report without a change anywhere else; an export added the same way is called
// once per budget and once per study; the built-ins are listed once and --format's error names them.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "results/report/report.hpp"
#include "results/reporters/reporter_registry.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;
using mhb::test_support::read_text;

// A table in reStructuredText: its title underlined, then a csv-table directive.
class RstTables final : public TableFormatReporter {
public:
    std::string_view name() const override { return "rst"; }
    std::string_view description() const override { return "reStructuredText: each table as <id>.rst"; }
    std::string render(const Table& table) const override {
        std::string out = table.title + '\n' + std::string(table.title.size(), '=') + "\n\n.. csv-table::\n";
        out += "   :header: " + quoted(table.header) + "\n\n";
        for (const auto& row : table.rows) {
            std::vector<std::string> cells;
            for (const auto& cell : row)
                cells.push_back(cell.text);
            out += "   " + quoted(cells) + '\n';
        }
        return out;
    }

private:
    static std::string quoted(const std::vector<std::string>& items) {
        std::string out;
        for (const auto& item : items)
            out += (out.empty() ? "\"" : ", \"") + item + '"';
        return out;
    }
};

// An export that counts its calls and writes a file per budget.
class CountingExport final : public Reporter {
public:
    std::string_view name() const override { return "test-counting-export"; }
    std::string_view description() const override { return "counts its calls (a test's)"; }
    ReporterKind kind() const override { return ReporterKind::every_report; }
    void write_budget(const BudgetReportContext& budget) const override {
        ++budgets;
        std::ofstream(budget.directory / "counted.txt") << budget.tables.size() << '\n';
    }
    std::optional<fs::path> write_study(const StudyReportContext& study) const override {
        ++studies;
        sections = study.budgets.size();
        return std::nullopt;
    }
    mutable int budgets = 0;
    mutable int studies = 0;
    mutable std::size_t sections = 0;
};

// Registered for one test only: the registry is process-wide.
class Registered {
public:
    explicit Registered(std::shared_ptr<const Reporter> reporter) : name_(reporter->name()) {
        register_reporter(std::move(reporter));
    }
    ~Registered() { unregister_reporter(name_); }
    Registered(const Registered&) = delete;
    Registered& operator=(const Registered&) = delete;

private:
    std::string name_;
};

// Two algorithms on a sphere, three paired runs each, at every budget given.
StudyData small_study(const std::vector<std::string>& budgets) {
    StudyData data;
    data.directory = "/nonexistent/reporter_study";
    std::int64_t id = 0;
    for (const auto& budget : budgets)
        for (const std::string algorithm : {"tlbo", "pso"})
            for (std::int64_t i = 0; i < 3; ++i) {
                RunRecord r;
                r.run_id = id++;
                r.algorithm = algorithm;
                r.problem = "sphere:dim=2";
                r.budget = budget;
                r.run_index = i;
                r.seed = 7 + static_cast<std::uint64_t>(i);
                r.evaluations = 100;
                r.iterations = 2;
                r.f_opt = 0.0;
                r.best_f = (algorithm == "tlbo" ? 1e-3 : 1e-2) * (1.0 + static_cast<double>(i));
                r.best_x = {0.01, -0.02};
                r.checkpoints = {{1, 8 * r.best_f}, {100, r.best_f}};
                r.curve = {{0, 50, 2 * r.best_f, {}}, {1, 100, r.best_f, {}}};
                data.runs.push_back(r);
            }
    return data;
}

ReportOptions options_into(const fs::path& out, std::set<std::string> formats) {
    ReportOptions options;
    options.out_dir = out;
    options.figures = false;
    options.formats = std::move(formats);
    return options;
}

TEST(Reporters, TheBuiltinsAreListedOnceInTheOrderAReportCallsThem) {
    std::vector<std::string> names;
    for (const auto& reporter : reporters())
        names.emplace_back(reporter->name());
    EXPECT_EQ(names,
              (std::vector<std::string>{"md", "tex", "csv", "console", "protocol-files", "ioh", "html"}));
    EXPECT_EQ(table_format_names(), (std::vector<std::string>{"md", "tex", "csv"}));
    EXPECT_EQ(default_table_formats(), (std::set<std::string>{"md", "tex", "csv"}));
    EXPECT_EQ(ReportOptions().formats, default_table_formats());
    const Registered rst(std::make_shared<RstTables>());
    EXPECT_THROW(register_reporter(std::make_shared<RstTables>()), std::logic_error)
        << "a name is one reporter";
}

TEST(Reporters, FormatErrorsNameTheRegisteredTableFormats) {
    EXPECT_EQ(table_format_error({"md", "csv"}), std::nullopt);
    EXPECT_EQ(table_format_error({"pdf"}), "--format: 'pdf' is not one of md, tex, csv");
    EXPECT_EQ(table_format_error({"ioh"}), "--format: 'ioh' is not one of md, tex, csv"); // an export
    EXPECT_EQ(table_format_error({}), "--format: choose at least one of md, tex, csv");
    const Registered rst(std::make_shared<RstTables>());
    EXPECT_EQ(table_format_error({"rst"}), std::nullopt);
    EXPECT_EQ(table_format_error({"pdf"}), "--format: 'pdf' is not one of md, tex, csv, rst");
}

TEST(Reporters, AFormatRegisteredByATestIsWrittenByBuildReport) {
    const Registered rst(std::make_shared<RstTables>());
    const fs::path out = test_support::fresh_temporary_path("mhb_reporters_", "report");
    std::ostringstream console;
    build_report(small_study({"iterations=2"}), options_into(out, {"md", "rst"}), console);
    for (const char* id : {"summary", "tests", "comparison"}) {
        ASSERT_TRUE(fs::exists(out / (std::string(id) + ".rst"))) << id;
        EXPECT_TRUE(fs::exists(out / (std::string(id) + ".md"))) << id;
        EXPECT_FALSE(fs::exists(out / (std::string(id) + ".tex"))) << id << ": not chosen";
    }
    const std::string summary = read_text(out / "summary.rst");
    EXPECT_EQ(summary.find("Summary"), 0u) << summary;
    EXPECT_NE(summary.find(".. csv-table::\n   :header: \"Problem\", \"Algorithm\""), std::string::npos)
        << summary;
    EXPECT_NE(read_text(out / "README.md").find("`<id>.md`, `<id>.rst`"), std::string::npos)
        << "the data dictionary names the format's files";
    EXPECT_TRUE(fs::exists(out / "report.md"));
    EXPECT_FALSE(fs::exists(out / "report.tex"));
    EXPECT_TRUE(fs::exists(out / "index.html")) << "every report writes the exports";
}

TEST(Reporters, AnExportIsCalledOncePerBudgetAndOncePerStudy) {
    const auto counting = std::make_shared<CountingExport>();
    const Registered registered(counting);
    const fs::path out = test_support::fresh_temporary_path("mhb_reporters_", "report");
    std::ostringstream console;
    const ReportOutcome outcome =
        build_report(small_study({"iterations=2", "evaluations=100"}), options_into(out, {"csv"}), console);
    EXPECT_EQ(counting->budgets, 2);
    EXPECT_EQ(counting->studies, 1);
    EXPECT_EQ(counting->sections, 2u);
    EXPECT_TRUE(fs::exists(out / "iterations_2" / "counted.txt"));
    EXPECT_TRUE(fs::exists(out / "evaluations_100" / "counted.txt"));
    EXPECT_EQ(outcome.html, out / "index.html") << "the page --open shows comes from the html reporter";
}

} // namespace
} // namespace mhb
