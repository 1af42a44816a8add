// The curve files and target hits against brute-force replays of real runs. The problem itself
// logs every evaluation it is asked for (f and x, in order: the log is the run), and every number
// of curves_iteration.csv, curves_evaluations.csv, parameters_iteration.csv and target_hits.csv is
// recomputed from that log the slow way, a prefix minimum per point. The runs are chosen to hit
// the cases that sampled grids got wrong: runs that stop inside an iteration (an evaluation budget
// that is no multiple of the population; a target reached mid-iteration), ties (a staircase f,
// where most evaluations equal the best so far without improving on it), and +inf values (f = +inf
// on half of the box, including, for some runs, every evaluation of the initial population).
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "algorithms/algorithm_registry.hpp"
#include "problems/problem_registry.hpp"
#include "results/analysis/curve_data.hpp"
#include "results/analysis/statistics.hpp"
#include "results/store/csv.hpp"
#include "runner/run/execute_run.hpp"
#include "support/numbers.hpp"

namespace mhb {
namespace {

using mhb::test_support::inf;

enum class Shape { plain, staircase, infinite_half };

struct Evaluation {
    double f = 0.0;
    Eigen::VectorXd x;
};

// A 3-D sphere, reshaped, that logs each evaluation. Not thread-safe: it says its evaluations are
// cheap, so the Objective asks for them one at a time, in the order it counts them.
class LoggedProblem final : public Problem {
public:
    explicit LoggedProblem(Shape shape) : base_(builtin_problems().create("sphere:dim=3")), shape_(shape) {}
    std::string name() const override { return "logged"; }
    Eigen::Index dimension() const override { return base_->dimension(); }
    const Box& bounds() const override { return base_->bounds(); }
    double evaluate(const Eigen::VectorXd& x) const override {
        double f = base_->evaluate(x);
        if (shape_ == Shape::staircase)
            f = std::floor(std::sqrt(f)); // the distance to the optimum, in whole units
        if (shape_ == Shape::infinite_half && x[0] > 0.0)
            f = inf;
        log_.push_back({f, x});
        return f;
    }
    std::optional<KnownOptimum> known_optimum() const override { return KnownOptimum{0.0, std::nullopt}; }
    std::vector<std::string> parameter_names() const override { return {"a", "b", "c"}; }

    const std::vector<Evaluation>& log() const { return log_; }

private:
    std::unique_ptr<Problem> base_;
    Shape shape_;
    mutable std::vector<Evaluation> log_;
};

struct ReplayedRun {
    RunRecord record;
    std::vector<Evaluation> log;

    // Best-so-far after the first n evaluations, and the x it was attained at (the first strict
    // improvement; the first evaluation sets x even at +inf), the slow way.
    [[nodiscard]] double best_f_after(std::int64_t n) const {
        double best = inf;
        for (std::int64_t i = 0; i < n; ++i)
            best = std::min(best, log[static_cast<std::size_t>(i)].f);
        return best;
    }
    [[nodiscard]] Eigen::VectorXd best_x_after(std::int64_t n) const {
        double best = inf;
        Eigen::VectorXd x;
        for (std::int64_t i = 0; i < n; ++i) {
            const Evaluation& e = log[static_cast<std::size_t>(i)];
            if (e.f < best || i == 0) {
                best = e.f;
                x = e.x;
            }
        }
        return x;
    }
    [[nodiscard]] std::int64_t evaluations() const { return static_cast<std::int64_t>(log.size()); }
    // The evaluation count at iteration k as the files define it: the end of iteration k, or the
    // run's end if that came first.
    [[nodiscard]] std::int64_t evaluations_at_iteration(std::int64_t k) const {
        const auto& curve = record.curve;
        return k < static_cast<std::int64_t>(curve.size()) ? curve[static_cast<std::size_t>(k)].evaluations
                                                           : evaluations();
    }
    // The last iteration with a row of its own: the last completed, or the one it stopped inside.
    [[nodiscard]] std::int64_t last_iteration() const {
        const auto completed = static_cast<std::int64_t>(record.curve.size());
        const bool stopped_inside = completed == 0 || evaluations() > record.curve.back().evaluations;
        return completed - 1 + (stopped_inside ? 1 : 0);
    }
};

struct GroupSpec {
    std::string algorithm;
    Shape shape;
    std::string problem;
    Budget budget;
};

ReplayedRun replay(const GroupSpec& spec, std::int64_t run_id, std::int64_t run_index) {
    const auto optimizer = builtin_algorithms().create(spec.algorithm);
    const LoggedProblem problem(spec.shape);
    RunRequest request;
    request.optimizer = optimizer.get();
    request.problem = &problem;
    request.algorithm_spec = spec.algorithm;
    request.problem_spec = spec.problem;
    request.run_id = run_id;
    request.run_index = run_index;
    request.seed = 1000 + static_cast<std::uint64_t>(run_id) * 7919;
    request.budget = spec.budget;
    request.budget_text = "replay";
    ReplayedRun run{execute_run(request), problem.log()};
    EXPECT_TRUE(run.record.ok) << run.record.message;
    // The log is the run: every evaluation the problem computed was counted, and no other.
    EXPECT_EQ(run.evaluations(), run.record.evaluations) << spec.algorithm << " on " << spec.problem;
    return run;
}

// Rows of a CSV text keyed by their first `key_columns` fields joined with '|'.
struct ParsedCsv {
    std::map<std::string, std::size_t> column;
    std::map<std::string, std::vector<std::string>> rows;
};
ParsedCsv parse(const std::string& text, std::size_t key_columns) {
    ParsedCsv parsed;
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    const auto header = csv_split(line);
    for (std::size_t i = 0; i < header.size(); ++i)
        parsed.column[header[i]] = i;
    while (std::getline(in, line)) {
        auto fields = csv_split(line);
        std::string key;
        for (std::size_t i = 0; i < key_columns; ++i)
            key += (i ? "|" : "") + fields[i];
        EXPECT_TRUE(parsed.rows.emplace(key, std::move(fields)).second) << "duplicate row " << key;
    }
    return parsed;
}

double number(const ParsedCsv& csv, const std::vector<std::string>& row, const std::string& column) {
    return std::stod(row.at(csv.column.at(column)));
}

// Equal as written at full precision: the same infinity, or within a few ulps of a mean's sum.
void expect_same(double expected, double actual, const std::string& where) {
    if (std::isinf(expected) || std::isinf(actual)) {
        EXPECT_EQ(expected, actual) << where;
        return;
    }
    EXPECT_NEAR(actual, expected, 1e-12 * std::max(1.0, std::fabs(expected))) << where;
}

// Mean and median the plain way (the quartiles are the statistics library's definition).
double plain_mean(const std::vector<double>& v) {
    double sum = 0.0;
    for (const double x : v)
        sum += x;
    return sum / static_cast<double>(v.size());
}
double plain_median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] == v[n / 2] ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

void expect_summary(const ParsedCsv& csv, const std::vector<std::string>& row,
                    const std::vector<double>& values, const std::string& where) {
    EXPECT_EQ(number(csv, row, "runs"), static_cast<double>(values.size())) << where;
    expect_same(plain_mean(values), number(csv, row, "mean"), where + " mean");
    expect_same(plain_median(values), number(csv, row, "median"), where + " median");
    const Summary s = summarize(values);
    expect_same(s.q25, number(csv, row, "q25"), where + " q25");
    expect_same(s.q75, number(csv, row, "q75"), where + " q75");
}

// The grid every run is sampled on, recomputed: round(10^(j/10)) up to n, and n itself.
std::set<std::int64_t> grid_up_to(std::int64_t n) {
    std::set<std::int64_t> grid{n};
    for (int j = 0;; ++j) {
        const auto g = std::llround(std::pow(10.0, j / 10.0));
        if (g > n)
            return grid;
        grid.insert(g);
    }
}

// The row of a run's (problem, algorithm) group whose remaining key fields are `rest` (empty when
// there is none). The label is the spec: the study has no algorithms.csv.
const std::vector<std::string>& group_row(const ParsedCsv& csv, const RunRecord& r, const std::string& rest) {
    static const std::vector<std::string> none;
    const auto it = csv.rows.find(r.problem + "|" + r.algorithm + "|" + r.algorithm + "|" + rest);
    return it == csv.rows.end() ? none : it->second;
}

class CurveReplay : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        const std::vector<GroupSpec> groups = {
            // 1037 is no multiple of ITLBO's class of 50: every run stops inside an iteration.
            {"itlbo", Shape::plain, "logged:plain", Budget{1037, std::nullopt, std::nullopt}},
            // Ties everywhere, and a target reached in the middle of an iteration.
            {"pso", Shape::staircase, "logged:staircase", Budget{3000, std::nullopt, 0.5}},
            // +inf on most of the box; some runs see nothing else for a while.
            {"de", Shape::infinite_half, "logged:infinite", Budget{777, std::nullopt, std::nullopt}},
            {"itlbo", Shape::infinite_half, "logged:infinite", Budget{4000, std::nullopt, 1e-3}},
        };
        runs_ = new std::vector<ReplayedRun>;
        data_ = new StudyData;
        std::int64_t id = 0;
        for (const auto& g : groups)
            for (std::int64_t i = 0; i < 6; ++i) {
                runs_->push_back(replay(g, id++, i));
                data_->runs.push_back(runs_->back().record);
            }
        index_ = new StudyIndex(*data_);
    }
    static void TearDownTestSuite() {
        delete index_;
        delete data_;
        delete runs_;
    }

    // The replayed runs of one (problem, algorithm) group, in run-index order.
    static std::map<std::string, std::vector<const ReplayedRun*>> groups() {
        std::map<std::string, std::vector<const ReplayedRun*>> by_group;
        for (const auto& run : *runs_)
            by_group[run.record.problem + "|" + run.record.algorithm].push_back(&run);
        return by_group;
    }

    static std::vector<ReplayedRun>* runs_;
    static StudyData* data_;
    static StudyIndex* index_;
};

std::vector<ReplayedRun>* CurveReplay::runs_ = nullptr;
StudyData* CurveReplay::data_ = nullptr;
StudyIndex* CurveReplay::index_ = nullptr;

TEST_F(CurveReplay, TheRunsCoverTheCasesThatMatter) {
    std::size_t stopped_inside = 0;
    std::size_t ties = 0;
    std::size_t infinite = 0;
    std::size_t stopped_on_target = 0;
    for (const auto& run : *runs_) {
        const auto& curve = run.record.curve;
        stopped_inside += curve.empty() || run.evaluations() > curve.back().evaluations ? 1U : 0U;
        double best = inf;
        for (const auto& e : run.log) {
            ties += e.f == best && std::isfinite(e.f) ? 1U : 0U;
            infinite += std::isinf(e.f) ? 1U : 0U;
            best = std::min(best, e.f);
        }
        stopped_on_target += run.record.evaluations_to_target ? 1U : 0U;
    }
    EXPECT_GE(stopped_inside, 12U);
    EXPECT_GT(ties, 20U);
    EXPECT_GT(infinite, 100U);
    EXPECT_GE(stopped_on_target, 6U);
}

TEST_F(CurveReplay, CurvesByIterationCarryEachRunsFinalValueAfterItStops) {
    const ParsedCsv csv = parse(fitness_curves_by_iteration(*index_), 4);
    std::size_t rows = 0;
    for (const auto& [group, runs] : groups()) {
        std::int64_t last = 0;
        for (const auto* run : runs)
            last = std::max(last, run->last_iteration());
        for (std::int64_t k = 0; k <= last; ++k) {
            const std::string where = group + " iteration " + std::to_string(k);
            std::vector<double> values;
            std::vector<double> evaluations;
            for (const auto* run : runs) {
                const std::int64_t n = run->evaluations_at_iteration(k);
                values.push_back(run->best_f_after(n));
                evaluations.push_back(static_cast<double>(n));
            }
            const auto& r = group_row(csv, runs.front()->record, std::to_string(k));
            ASSERT_FALSE(r.empty()) << where << ": no row";
            expect_summary(csv, r, values, where);
            expect_same(plain_mean(evaluations), number(csv, r, "evaluations_mean"), where + " evaluations");
            ++rows;
        }
    }
    EXPECT_EQ(csv.rows.size(), rows) << "rows beyond each group's last iteration";
}

TEST_F(CurveReplay, CurvesByEvaluationsAreEachRunsBestSoFarAtExactlyThatCount) {
    const ParsedCsv csv = parse(fitness_curves_by_evaluations(*index_), 4);
    std::size_t rows = 0;
    for (const auto& [group, runs] : groups()) {
        std::set<std::int64_t> keys;
        for (const auto* run : runs) {
            const auto grid = grid_up_to(run->evaluations());
            keys.insert(grid.begin(), grid.end());
        }
        for (const std::int64_t e : keys) {
            std::vector<double> values;
            for (const auto* run : runs)
                values.push_back(run->best_f_after(std::min(e, run->evaluations())));
            const auto& r = group_row(csv, runs.front()->record, std::to_string(e));
            ASSERT_FALSE(r.empty()) << group << " at " << e << ": no row";
            expect_summary(csv, r, values, group + " at " + std::to_string(e));
            ++rows;
        }
    }
    EXPECT_EQ(csv.rows.size(), rows);
}

TEST_F(CurveReplay, ParametersByIterationFollowTheSameRule) {
    const ParsedCsv csv = parse(parameter_curves_by_iteration(*index_), 5);
    std::size_t rows = 0;
    const std::vector<std::string> names = {"a", "b", "c"};
    for (const auto& [group, runs] : groups()) {
        std::int64_t last = 0;
        for (const auto* run : runs)
            last = std::max(last, run->last_iteration());
        for (std::size_t j = 0; j < names.size(); ++j)
            for (std::int64_t k = 0; k <= last; ++k) {
                const std::string where = group + " " + names[j] + " iteration " + std::to_string(k);
                std::vector<double> values;
                for (const auto* run : runs)
                    values.push_back(
                        run->best_x_after(run->evaluations_at_iteration(k))[static_cast<Eigen::Index>(j)]);
                const auto& r = group_row(csv, runs.front()->record, names[j] + "|" + std::to_string(k));
                ASSERT_FALSE(r.empty()) << where << ": no row";
                EXPECT_EQ(number(csv, r, "runs"), static_cast<double>(values.size())) << where;
                expect_same(plain_mean(values), number(csv, r, "mean"), where);
                expect_same(standard_deviation(values), number(csv, r, "std"), where + " std");
                ++rows;
            }
    }
    EXPECT_EQ(csv.rows.size(), rows);
}

TEST_F(CurveReplay, TargetHitsAreTheEvaluationThatFirstReachedEachGap) {
    const ParsedCsv csv = parse(target_hits(*index_), 5);
    std::size_t off_grid = 0;
    for (const auto& run : *runs_)
        for (const double gap : ecdf_target_gaps()) {
            std::string expected;
            double best = inf;
            for (std::size_t i = 0; i < run.log.size(); ++i) {
                best = std::min(best, run.log[i].f);
                if (best <= gap) {
                    expected = std::to_string(i + 1);
                    break;
                }
            }
            const std::string key = run.record.problem + "|" + run.record.algorithm + "|" +
                                    run.record.algorithm + "|" + std::to_string(run.record.run_index) + "|" +
                                    csv_number(gap);
            ASSERT_TRUE(csv.rows.count(key)) << key;
            EXPECT_EQ(csv.rows.at(key)[csv.column.at("evaluations")], expected) << key;
            if (!expected.empty() && !grid_up_to(run.evaluations()).count(std::stoll(expected)))
                ++off_grid;
        }
    // A sampled grid could not have given these.
    EXPECT_GT(off_grid, 20U);
}

} // namespace
} // namespace mhb
