// Each built-in optimiser and problem family pins the numbers its implementation version computes:
// every row of tests/data/implementation_versions.csv names a component, its version, a spec and
// the number that version gives for it (an optimiser: best_f of one fixed short run on rastrigin;
// a problem: f at a fixed interior point), with 17 significant digits. The version is part of every
// run's identity (runner/execution/run_identity.hpp), so numbers that change without a bump would let a study
// mix old and new runs under one identity: this test is what makes a developer bump it.
//
// MHB_PRINT_GOLDEN=1 prints the rows this build computes (to write new rows, after a bump).
#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/problem_registry.hpp"
#include "results/store/csv.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/study.hpp"

namespace mhb {
namespace {

struct GoldenRow {
    std::string kind; // "algorithm" or "problem"
    std::string name; // the registry name
    int version = 0;
    std::string spec;
    std::string value; // %.17g
};

const char* const table_path = MHB_TEST_DATA_DIR "/implementation_versions.csv";

std::vector<GoldenRow> golden_rows() {
    const CsvTable table = read_csv(table_path);
    std::vector<GoldenRow> rows;
    const auto column = [&](const char* name) { return table.column(name); };
    const std::size_t kind = column("kind"), name = column("name"), version = column("version"),
                      spec = column("spec"), value = column("value");
    for (std::size_t r = 0; r < table.rows.size(); ++r)
        rows.push_back({table.rows[r][kind], table.rows[r][name], static_cast<int>(table.integer(r, version)),
                        table.rows[r][spec], table.rows[r][value]});
    return rows;
}

std::string exact(double value) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", value);
    return buf;
}

// best_f of one run of `algorithm` on 5-D Rastrigin, 1000 evaluations, study seed 1.
std::string algorithm_number(const std::string& algorithm) {
    Study study;
    study.algorithms = {algorithm};
    study.problems = {"rastrigin:dim=5"};
    study.runs = 1;
    Budget budget;
    budget.max_evaluations = 1000;
    study.budgets = {budget};
    const PreparedStudy prepared = prepare_study(study);
    const RunRecord record = execute_run(prepared.request(0));
    return record.ok ? exact(record.best_f) : "failed: " + record.message;
}

// f at a fixed point inside the box, each coordinate at an irregular fraction of its range (so
// that no symmetry of a function hides a change). A problem random per run (f0) is evaluated as a
// run evaluates it: its instance for the run seed 1, so that the row pins the run's stream.
std::string problem_number(const std::string& spec) {
    const auto shared = builtin_problems().create(spec);
    const auto own = shared->for_run(1);
    const Problem* problem = own ? own.get() : shared.get();
    const Box& box = problem->bounds();
    Eigen::VectorXd x(box.dimension());
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        const double golden = 0.6180339887498949 * static_cast<double>(i + 1);
        const double fraction = 0.1 + 0.8 * (golden - static_cast<double>(static_cast<long>(golden)));
        x[i] = box.lower[i] + fraction * (box.upper[i] - box.lower[i]);
    }
    return exact(problem->evaluate(x));
}

// `spec` with @SOURCE@ replaced by the source tree (the external protocol's reference clients
// are named by path).
std::string with_source(std::string spec) {
    for (auto at = spec.find("@SOURCE@"); at != std::string::npos; at = spec.find("@SOURCE@"))
        spec.replace(at, 8, MHB_SOURCE_DIR);
    return spec;
}

std::string computed(const GoldenRow& row) {
    return row.kind == "algorithm" ? algorithm_number(with_source(row.spec))
                                   : problem_number(with_source(row.spec));
}

int registered_version(const GoldenRow& row) {
    return row.kind == "algorithm" ? builtin_algorithms().find(row.name).version
                                   : builtin_problems().find(row.name).version;
}

TEST(ImplementationVersions, EveryBuiltInHasGoldenNumbers) {
    std::set<std::pair<std::string, std::string>> listed;
    for (const GoldenRow& row : golden_rows())
        listed.emplace(row.kind, row.name);
    for (const auto& entry : builtin_algorithms().entries())
        EXPECT_EQ(listed.count({"algorithm", entry.name}), 1U)
            << "algorithm '" << entry.name << "' has no row in " << table_path
            << "; add one (MHB_PRINT_GOLDEN=1 prints the numbers of listed rows)";
    for (const auto& entry : builtin_problems().entries())
        EXPECT_EQ(listed.count({"problem", entry.name}), 1U)
            << "problem '" << entry.name << "' has no row in " << table_path << "; add one";
}

TEST(ImplementationVersions, NumbersChangeOnlyWithTheVersion) {
    const bool print = std::getenv("MHB_PRINT_GOLDEN") != nullptr;
    for (const GoldenRow& row : golden_rows()) {
        const int version = registered_version(row);
        const std::string value = computed(row);
        if (print)
            std::printf("%s,%s,%d,%s,%s\n", row.kind.c_str(), row.name.c_str(), version,
                        csv_field(row.spec).c_str(), value.c_str());
        if (version != row.version) {
            ADD_FAILURE() << row.kind << " '" << row.name << "' is version " << version << " but its row for "
                          << row.spec << " is for version " << row.version << ": update the row in "
                          << table_path << " to version " << version << " and value " << value;
            continue;
        }
        EXPECT_EQ(value, row.value) << row.kind << " '" << row.name << "' (" << row.spec << ") computes "
                                    << value << " where version " << version << " computed " << row.value
                                    << ". If the change is intended, bump its implementation "
                                    << "version in its registration (" << row.kind
                                    << "s/) so that stored runs of the old version "
                                    << "are not mixed with new ones, and update its rows in " << table_path;
    }
}

} // namespace
} // namespace mhb
