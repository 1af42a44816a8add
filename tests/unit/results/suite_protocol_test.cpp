// A suite protocol added at run time, in this file alone: the registry names it beside the
// built-ins, the runner accepts a study that names it (`protocol = tiny`) and asks it to check
// that study, the dry run prints its line, and the report of the study adds its table. The paper's
// Tables 2-4 stay a protocol in force without being named.
#include <filesystem>
#include <gtest/gtest.h>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "results/protocols/protocol_registry.hpp"
#include "results/report/report.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/study/dry_run.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

// Sphere problems only, and one table: the number of runs per problem.
class TinyProtocol final : public SuiteProtocol {
public:
    [[nodiscard]] std::string_view name() const override { return "tiny"; }
    [[nodiscard]] std::string_view title() const override { return "Tiny"; }
    [[nodiscard]] std::string_view description() const override { return "a table of runs per problem"; }
    void check_study(const ProtocolStudy& study, std::vector<std::string>& errors) const override {
        for (const auto& problem : study.problems)
            if (problem.family != "sphere")
                errors.push_back("protocol tiny: problem '" + problem.spec + "' is not a sphere");
    }
    [[nodiscard]] std::string dry_run_line() const override { return "protocol: tiny (a table of runs)"; }
    [[nodiscard]] std::vector<Table> tables(const StudyIndex& index, const std::string& /*reference*/,
                                            double /*alpha*/) const override {
        Table t;
        t.id = "tiny_runs";
        t.title = "Runs per problem (protocol tiny)";
        t.header = {"Problem", "Runs"};
        for (const auto& problem : index.problems()) {
            std::size_t runs = 0;
            for (const auto& algorithm : index.algorithms_on(problem))
                runs += index.find(problem, algorithm)->runs.size();
            t.add_row({text_cell(problem), text_cell(std::to_string(runs))});
        }
        t.caption = "Every run of the problem.";
        return {t};
    }
};

// Once per process: the registry refuses a name twice.
void register_tiny() {
    static const bool registered = [] {
        register_protocol(std::make_unique<TinyProtocol>());
        return true;
    }();
    (void)registered;
}

const char* const tiny_study = "protocol = tiny\n"
                               "algorithms = random-search\n"
                               "problems = sphere:dim={2,3}\n"
                               "runs = 2\n"
                               "seed = 1\n"
                               "budget = iterations=5\n";

std::vector<std::string> names_of(const std::vector<const SuiteProtocol*>& protocols) {
    std::vector<std::string> out;
    for (const SuiteProtocol* p : protocols)
        out.emplace_back(p->name());
    return out;
}

TEST(SuiteProtocolRegistry, AProtocolRegisteredAtRunTimeIsNamedLikeTheBuiltIns) {
    register_tiny();
    ASSERT_NE(find_protocol("tiny"), nullptr);
    EXPECT_EQ(find_protocol("tiny")->title(), "Tiny");
    EXPECT_EQ(protocol_names(), "cec2017, cec2022, pmsm-paper, tiny");
    EXPECT_THROW(register_protocol(std::make_unique<TinyProtocol>()), std::logic_error);
    // The paper's tables are a protocol a study names (the paper presets do); none is in force unnamed.
    ASSERT_NE(find_protocol("pmsm-paper"), nullptr);
    EXPECT_EQ(names_of(protocols_in_force("")), std::vector<std::string>{});
    EXPECT_EQ(names_of(protocols_in_force("tiny")), (std::vector<std::string>{"tiny"}));
    EXPECT_EQ(names_of(protocols_in_force("pmsm-paper")), (std::vector<std::string>{"pmsm-paper"}));
}

TEST(SuiteProtocolRunner, TheRunnerAcceptsAStudyNamingItAndAsksItToCheckTheStudy) {
    register_tiny();
    const Study s = parse_study_ini(tiny_study, "tiny.ini");
    EXPECT_EQ(s.protocol, "tiny");
    const PreparedStudy prepared = prepare_study(s);
    EXPECT_NE(study_ini(prepared.study).find("\nprotocol = tiny\n"), std::string::npos);
    EXPECT_NE(dry_run_text(prepared, fs::temp_directory_path() / "mhb-tiny-dry", 1)
                  .find("\nprotocol: tiny (a table of runs)\n"),
              std::string::npos);

    Study wrong = s;
    wrong.problems = {"sphere:dim=2", "rastrigin:dim=2"};
    try {
        (void)prepare_study(wrong);
        ADD_FAILURE() << "a study against the protocol's check was prepared";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "protocol tiny: problem 'rastrigin:dim=2' is not a sphere");
    }
}

TEST(SuiteProtocolReport, TheReportOfAStudyFollowingItAddsItsTable) {
    register_tiny();
    const PreparedStudy prepared = prepare_study(parse_study_ini(tiny_study, "tiny.ini"));
    const fs::path dir = fs::temp_directory_path() / "mhb-suite-protocol-test";
    fs::remove_all(dir);
    {
        StudyWriter writer(dir, study_ini(prepared.study), "threads = test\n", prepared.parameter_columns,
                           false);
        ASSERT_EQ(run_study(prepared, writer).kept, 4);
    }
    ReportOptions options;
    options.figures = false;
    options.console_tables = true; // --tables: its table on the console too
    std::ostringstream console;
    (void)build_report(load_study(dir), options, console);
    const std::string table = test_support::read_text(dir / "report" / "tiny_runs.md");
    EXPECT_NE(table.find("Runs per problem (protocol tiny)"), std::string::npos) << table;
    EXPECT_NE(table.find("sphere:dim=3"), std::string::npos) << table;
    EXPECT_NE(console.str().find("Runs per problem (protocol tiny)"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "report" / "cec")); // it writes no files
    fs::remove_all(dir);
}

} // namespace
} // namespace mhb
