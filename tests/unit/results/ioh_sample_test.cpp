// The IOHprofiler export against files IOHexperimenter wrote (tests/data/ioh/README.md): the same
// points replayed through mhbench's bbob problems must give the same files, headers, JSON keys and
// layout, function ids and names, dimensions, instances, improving evaluations and values (raw_y
// to rounding: IOH logs the value before adding f_opt, mhbench subtracts it); and raw_y against
// COCO's own values (tests/data/bbob_public_sample.csv).
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string_view>

#include "problems/problem_registry.hpp"
#include "results/exports/ioh_export.hpp"
#include "results/store/csv.hpp"
#include "runner/run/execute_run.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {

namespace fs = std::filesystem;
using mhb::test_support::read_text;

const fs::path ioh_sample_dir = fs::path(MHB_TEST_DATA_DIR) / "ioh" / "ioh_sample";

fs::path fresh_ioh_sample_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("mhb_ioh_sample_" + name);
    fs::remove_all(dir);
    return dir;
}

// The sample's points: a 31-bit LCG, each coordinate (s mod 4001 - 2000) / 400.
Eigen::VectorXd lcg_point(std::uint64_t& s, Eigen::Index dimension) {
    Eigen::VectorXd x(dimension);
    for (Eigen::Index i = 0; i < dimension; ++i) {
        s = (s * 1103515245u + 12345u) % 2147483648u;
        x[i] = static_cast<double>(static_cast<std::int64_t>(s % 4001) - 2000) / 400.0;
    }
    return x;
}

// The sample's runs: run 0 and 1 60 points, run 2 until an evaluation at or after the 10th improves.
class LcgReplay final : public Optimizer {
public:
    explicit LcgReplay(int run) : run_(run) {}
    std::string name() const override { return "replay"; }
    BoundPolicy bound_policy() const override { return BoundPolicy::none; }
    void run(Objective& objective, Rng&) const override {
        std::uint64_t s = 1000u * static_cast<std::uint64_t>(run_) + 1u;
        for (int k = 1;; ++k) {
            Eigen::VectorXd x = lcg_point(s, objective.dimension());
            const double before = objective.best_f();
            const double f = objective.evaluate(x);
            if (run_ < 2 ? k == 60 : k >= 10 && f < before)
                return;
        }
    }

private:
    int run_;
};

// One given point.
class OnePoint final : public Optimizer {
public:
    explicit OnePoint(Eigen::VectorXd x) : x_(std::move(x)) {}
    std::string name() const override { return "point"; }
    BoundPolicy bound_policy() const override { return BoundPolicy::none; }
    void run(Objective& objective, Rng&) const override {
        Eigen::VectorXd x = x_;
        objective.evaluate(x);
    }

private:
    Eigen::VectorXd x_;
};

RunRecord run_on(const Optimizer& optimizer, const std::string& algorithm, const std::string& problem_spec,
                 std::int64_t run_id, std::int64_t run_index, std::int64_t evaluations) {
    const auto problem = builtin_problems().create(problem_spec);
    RunRequest request;
    request.optimizer = &optimizer;
    request.problem = problem.get();
    request.algorithm_spec = algorithm;
    request.problem_spec = problem_spec;
    request.run_id = run_id;
    request.run_index = run_index;
    request.budget = Budget{evaluations, std::nullopt, std::nullopt};
    request.budget_text = "evaluations=" + std::to_string(evaluations);
    return execute_run(request);
}

// The sample study replayed by mhbench: suite order (function, dimension, instance), three runs each.
StudyData replayed_sample() {
    StudyData data;
    const LcgReplay runs[3] = {LcgReplay(0), LcgReplay(1), LcgReplay(2)};
    std::int64_t id = 0;
    for (int f : {1, 8, 15})
        for (int dim : {2, 5})
            for (int instance : {1, 3}) {
                const std::string spec = "bbob:dim=" + std::to_string(dim) + ",f=" + std::to_string(f) +
                                         ",instance=" + std::to_string(instance);
                for (int r = 0; r < 3; ++r) {
                    // A budget run 2 never reaches: the optimiser decides when a run ends.
                    data.runs.push_back(run_on(runs[r], "replay", spec, id++, r, 100000));
                    EXPECT_TRUE(data.runs.back().ok) << data.runs.back().message;
                }
            }
    return data;
}

std::set<std::string> relative_files(const fs::path& root) {
    std::set<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.is_regular_file())
            files.insert(fs::relative(entry.path(), root).generic_string());
    return files;
}

bool close(double a, double b) {
    return std::fabs(a - b) <= 2e-10 + 1e-13 * std::fabs(b);
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

// JSON as tokens: strings, numbers, and every other character (whitespace included, so that the
// layout must match too).
std::vector<std::string> tokens_of(const std::string& text) {
    std::vector<std::string> tokens;
    for (std::size_t i = 0; i < text.size();) {
        std::size_t j = i + 1;
        if (text[i] == '"') {
            j = text.find('"', i + 1) + 1;
        } else if (text[i] == '-' || std::isdigit(static_cast<unsigned char>(text[i]))) {
            while (j < text.size() && (std::isdigit(static_cast<unsigned char>(text[j])) ||
                                       std::string_view(".eE+-").find(text[j]) != std::string_view::npos))
                ++j;
        }
        tokens.push_back(text.substr(i, j - i));
        i = j;
    }
    return tokens;
}

bool is_number(const std::string& token) {
    return !token.empty() && (token[0] == '-' || std::isdigit(static_cast<unsigned char>(token[0])));
}

TEST(IohSample, ExportOfTheSameRunsMatchesWhatIohWrote) {
    const StudyData data = replayed_sample();
    const StudyIndex index(data);
    const fs::path dir = fresh_ioh_sample_dir("replay");
    const IohExportSummary summary = write_ioh_export(index, dir);
    EXPECT_EQ(summary.approximate_runs, 0u);
    EXPECT_EQ(summary.none_values, 0u);
    EXPECT_EQ(summary.runs_left_out, 0u);
    const fs::path ours = dir / "replay";
    const std::set<std::string> files = relative_files(ioh_sample_dir);
    ASSERT_EQ(files.size(), 9u);
    EXPECT_EQ(relative_files(ours), files); // same names: ids, function names, dimensions

    std::size_t rows = 0;
    std::size_t identical_values = 0;
    for (const std::string& file : files) {
        const std::string theirs_text = read_text(ioh_sample_dir / file);
        const std::string ours_text = read_text(ours / file);
        if (fs::path(file).extension() == ".dat") {
            const auto theirs = lines_of(theirs_text);
            const auto mine = lines_of(ours_text);
            ASSERT_EQ(mine.size(), theirs.size()) << file;
            for (std::size_t i = 0; i < theirs.size(); ++i) {
                const auto space = theirs[i].find(' ');
                ASSERT_NE(space, std::string::npos) << file;
                // The header and the evaluation column exactly; raw_y to rounding.
                EXPECT_EQ(mine[i].substr(0, space + 1), theirs[i].substr(0, space + 1))
                    << file << ':' << i + 1;
                if (theirs[i] == "evaluations raw_y") {
                    EXPECT_EQ(mine[i], theirs[i]);
                    continue;
                }
                const double a = std::stod(mine[i].substr(space + 1));
                const double b = std::stod(theirs[i].substr(space + 1));
                EXPECT_TRUE(close(a, b)) << file << ':' << i + 1 << ": " << mine[i] << " vs " << theirs[i];
                identical_values += mine[i] == theirs[i];
                ++rows;
            }
            continue;
        }
        // JSON: the same tokens and whitespace; the algorithm's info (free text) aside, and the
        // best y to rounding. Coordinates of x are the same doubles: the same shortest text.
        const auto theirs = tokens_of(theirs_text);
        const auto mine = tokens_of(ours_text);
        ASSERT_EQ(mine.size(), theirs.size()) << file << "\n" << ours_text;
        for (std::size_t i = 0; i < theirs.size(); ++i) {
            // Tokens of a value: its key, ':', ' ', the value.
            if (i >= 3 && theirs[i - 3] == "\"info\"")
                continue;
            if (is_number(theirs[i]) && i >= 3 && theirs[i - 3] == "\"y\"") {
                EXPECT_TRUE(close(std::stod(mine[i]), std::stod(theirs[i])))
                    << file << ": y " << mine[i] << " vs " << theirs[i];
                continue;
            }
            if (theirs[i] == "\"version\"") {
                EXPECT_EQ(theirs[i + 3], std::string("\"") + ioh_format_version + "\"");
            }
            EXPECT_EQ(mine[i], theirs[i]) << file << ", token " << i;
        }
    }
    EXPECT_GT(rows, 150u);
    // Most values are the same text to all ten decimals (the rest differ in the last ones).
    EXPECT_GT(identical_values * 10, rows * 9) << identical_values << " of " << rows;
}

TEST(IohSample, RawYOfBbobIsCocosFMinusFOpt) {
    const CsvTable table = read_csv(fs::path(MHB_TEST_DATA_DIR) / "bbob_public_sample.csv");
    StudyData data;
    std::vector<std::unique_ptr<OnePoint>> optimizers;
    std::map<std::string, std::int64_t> runs_of;
    // Expected raw_y and its tolerance by .dat file, in the order runs appear there: problems by
    // first appearance, then run index.
    struct Expected {
        std::string dat;
        double raw_y = 0.0;
        double tolerance = 0.0;
    };
    std::map<std::string, std::vector<Expected>> by_problem;
    std::vector<std::string> problem_order;
    for (std::size_t row = 0; row < table.rows.size(); ++row) {
        const std::int64_t f = table.integer(row, table.column("function"));
        const std::int64_t dim = table.integer(row, table.column("dimension"));
        const std::string spec = "bbob:dim=" + std::to_string(dim) + ",f=" + std::to_string(f) +
                                 ",instance=" + table.rows[row][table.column("instance")];
        std::istringstream in(table.rows[row][table.column("x")]);
        Eigen::VectorXd x(dim);
        for (Eigen::Index i = 0; i < dim; ++i)
            in >> x[i];
        optimizers.push_back(std::make_unique<OnePoint>(x));
        data.runs.push_back(
            run_on(*optimizers.back(), "point", spec, static_cast<std::int64_t>(row), runs_of[spec]++, 1));
        if (by_problem.count(spec) == 0)
            problem_order.push_back(spec);
        const double coco_f = table.number(row, table.column("f"));
        const std::string dat = "data_f" + std::to_string(f) + "_" + ioh_function(spec).name +
                                "/IOHprofiler_f" + std::to_string(f) + "_DIM" + std::to_string(dim) + ".dat";
        // f to 1e-9 relative (the BBOB tests' tolerance), and IOH's ten decimals.
        by_problem[spec].push_back({dat, coco_f - table.number(row, table.column("f_opt")),
                                    1e-9 * std::max(1.0, std::fabs(coco_f)) + 1e-10});
    }
    std::map<std::string, std::vector<Expected>> expected; // by .dat
    for (const auto& spec : problem_order)
        for (const Expected& e : by_problem[spec])
            expected[e.dat].push_back(e);

    const fs::path dir = fresh_ioh_sample_dir("coco");
    write_ioh_export(StudyIndex(data), dir);
    std::size_t compared = 0;
    for (const auto& [dat, values] : expected) {
        const auto lines = lines_of(read_text(dir / "point" / dat));
        ASSERT_EQ(lines.size(), 2 * values.size()) << dat; // a header and one row per run
        for (std::size_t i = 0; i < values.size(); ++i) {
            EXPECT_EQ(lines[2 * i], "evaluations raw_y");
            ASSERT_EQ(lines[2 * i + 1].rfind("1 ", 0), 0u) << lines[2 * i + 1];
            const double raw_y = std::stod(lines[2 * i + 1].substr(2));
            EXPECT_NEAR(raw_y, values[i].raw_y, values[i].tolerance) << dat << " run " << i;
            ++compared;
        }
    }
    EXPECT_EQ(compared, table.rows.size());
}

} // namespace
} // namespace mhb
