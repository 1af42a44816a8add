#include "runner/plugins/plugin_check.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "algorithms/sampling.hpp"
#include "problems/core/parameters.hpp"
#include "problems/core/rng.hpp"
#include "runner/run/execute_run.hpp"

namespace mhb {
namespace {

// Numbers in the lines at full precision, the shortest text that reads back the same.
std::string number(double value) {
    return format_real(value);
}

// A problem that forwards everything to `inner` and watches what it is asked: how many points,
// and the first that lies outside the box or is not finite.
class WatchedProblem final : public Problem {
public:
    explicit WatchedProblem(const Problem& inner) : inner_(inner) {}

    std::string name() const override { return inner_.name(); }
    Eigen::Index dimension() const override { return inner_.dimension(); }
    const Box& bounds() const override { return inner_.bounds(); }
    std::optional<KnownOptimum> known_optimum() const override { return inner_.known_optimum(); }
    std::vector<std::string> parameter_names() const override { return inner_.parameter_names(); }
    std::optional<Eigen::VectorXd> true_parameters() const override { return inner_.true_parameters(); }
    bool parallel_evaluation() const override { return inner_.parallel_evaluation(); }

    double evaluate(const Eigen::VectorXd& x) const override {
        const std::int64_t n = ++count_;
        for (Eigen::Index k = 0; k < x.size(); ++k)
            if (!(x[k] >= bounds().lower[k] && x[k] <= bounds().upper[k])) {
                const std::lock_guard<std::mutex> lock(mutex_);
                if (first_outside_.empty())
                    first_outside_ = "evaluation " + std::to_string(n) + ": x[" + std::to_string(k) +
                                     "] = " + number(x[k]) + " is outside [" + number(bounds().lower[k]) +
                                     ", " + number(bounds().upper[k]) + "]";
                break;
            }
        return inner_.evaluate(x);
    }

    [[nodiscard]] std::int64_t count() const { return count_.load(); }
    [[nodiscard]] std::string first_outside() const {
        const std::lock_guard<std::mutex> lock(mutex_);
        return first_outside_;
    }

private:
    const Problem& inner_;
    mutable std::atomic<std::int64_t> count_{0};
    mutable std::mutex mutex_;
    mutable std::string first_outside_;
};

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](double x, double y) { return same_bits(x, y); });
}

// Two records of one run hold the same numbers, bit for bit (the run's wall time is not in it).
bool same_record(const RunRecord& a, const RunRecord& b) {
    const auto same_samples = [](const std::vector<CheckpointSample>& x,
                                 const std::vector<CheckpointSample>& y) {
        return x.size() == y.size() &&
               std::equal(x.begin(), x.end(), y.begin(), [](const auto& p, const auto& q) {
                   return p.evaluations == q.evaluations && same_bits(p.best_f, q.best_f);
               });
    };
    if (a.ok != b.ok || a.message != b.message || !same_bits(a.best_f, b.best_f) ||
        !same_bits(a.best_x, b.best_x) || a.evaluations != b.evaluations || a.iterations != b.iterations ||
        a.curve.size() != b.curve.size() || !same_samples(a.checkpoints, b.checkpoints) ||
        a.improvements.has_value() != b.improvements.has_value())
        return false;
    for (std::size_t i = 0; i < a.curve.size(); ++i)
        if (a.curve[i].iteration != b.curve[i].iteration ||
            a.curve[i].evaluations != b.curve[i].evaluations ||
            !same_bits(a.curve[i].best_f, b.curve[i].best_f) ||
            !same_bits(a.curve[i].best_x, b.curve[i].best_x))
            return false;
    return !a.improvements || (same_samples(a.improvements->points, b.improvements->points) &&
                               same_bits(a.improvements->last_f, b.improvements->last_f));
}

struct WatchedRun {
    RunRecord record;
    std::int64_t asked = 0;    // points the problem was asked to evaluate
    std::string first_outside; // empty when every point was inside the box
};

class OptimizerCheck {
public:
    OptimizerCheck(const Optimizer& optimizer, std::string algorithm_spec, const Problem& problem,
                   std::string problem_spec, const PluginCheckOptions& options)
        : optimizer_(optimizer), algorithm_spec_(std::move(algorithm_spec)), problem_(problem),
          problem_spec_(std::move(problem_spec)), options_(options) {}

    std::vector<CheckResult> run() {
        std::vector<WatchedRun> serial;
        for (int r = 0; r < options_.runs; ++r)
            serial.push_back(watched_run(r));
        std::vector<CheckResult> results{runs_finished(serial)};
        if (results.back().verdict == CheckVerdict::fail)
            return results;
        results.push_back(bounds(serial));
        results.push_back(budget(serial));
        results.push_back(same_seed(serial.front()));
        results.push_back(threads(serial));
        return results;
    }

private:
    WatchedRun watched_run(int r) const {
        const WatchedProblem watched(problem_);
        RunRequest request;
        request.optimizer = &optimizer_;
        request.problem = &watched;
        request.algorithm_spec = algorithm_spec_;
        request.problem_spec = problem_spec_;
        request.run_id = r;
        request.run_index = r;
        request.seed = derive_seed(options_.seed, problem_spec_, static_cast<std::uint64_t>(r));
        request.budget.max_evaluations = options_.evaluations;
        WatchedRun out;
        out.record = execute_run(request);
        out.asked = watched.count();
        out.first_outside = watched.first_outside();
        return out;
    }

    CheckResult runs_finished(const std::vector<WatchedRun>& runs) const {
        for (std::size_t r = 0; r < runs.size(); ++r)
            if (!runs[r].record.ok)
                return {"runs", CheckVerdict::fail,
                        "run " + std::to_string(r) + " failed: " + runs[r].record.message};
        return {"runs", CheckVerdict::pass,
                std::to_string(runs.size()) +
                    " runs finished, best f of run 0: " + number(runs[0].record.best_f)};
    }

    static CheckResult bounds(const std::vector<WatchedRun>& runs) {
        std::int64_t points = 0;
        for (std::size_t r = 0; r < runs.size(); ++r) {
            if (!runs[r].first_outside.empty())
                return {"bounds", CheckVerdict::fail,
                        "run " + std::to_string(r) + ", " + runs[r].first_outside};
            points += runs[r].asked;
        }
        return {"bounds", CheckVerdict::pass,
                std::to_string(points) + " points evaluated, every one inside the box"};
    }

    CheckResult budget(const std::vector<WatchedRun>& runs) const {
        std::string early;
        for (std::size_t r = 0; r < runs.size(); ++r) {
            const RunRecord& record = runs[r].record;
            const std::string run = "run " + std::to_string(r) + ": ";
            if (runs[r].asked != record.evaluations)
                return {"budget", CheckVerdict::fail,
                        run + "the problem was asked " + std::to_string(runs[r].asked) +
                            " times, the objective counted " + std::to_string(record.evaluations)};
            if (record.evaluations > options_.evaluations)
                return {"budget", CheckVerdict::fail,
                        run + std::to_string(record.evaluations) + " evaluations, past the budget of " +
                            std::to_string(options_.evaluations)};
            if (record.evaluations < options_.evaluations && early.empty())
                early = run + "stopped after " + std::to_string(record.evaluations) + " of " +
                        std::to_string(options_.evaluations) + " evaluations";
        }
        if (!early.empty())
            return {"budget", CheckVerdict::warn,
                    early + " (fine for a method that has converged; a study reports it)"};
        return {"budget", CheckVerdict::pass,
                "every run made exactly " + std::to_string(options_.evaluations) +
                    " evaluations, each one counted by the objective"};
    }

    CheckResult same_seed(const WatchedRun& first) const {
        const WatchedRun again = watched_run(0);
        if (!same_record(first.record, again.record))
            return {"same seed", CheckVerdict::fail,
                    "run 0 twice with seed " + std::to_string(first.record.seed) + ": best f " +
                        number(first.record.best_f) + ", then " + number(again.record.best_f) +
                        " (every random number must come from the Rng passed to run())"};
        return {"same seed", CheckVerdict::pass, "run 0 twice: the same record, bit for bit"};
    }

    CheckResult threads(const std::vector<WatchedRun>& serial) const {
        std::vector<WatchedRun> parallel(serial.size());
        tbb::task_arena arena(std::max(2, options_.threads));
        arena.execute([&] {
            tbb::parallel_for(std::size_t{0}, parallel.size(),
                              [&](std::size_t r) { parallel[r] = watched_run(static_cast<int>(r)); });
        });
        for (std::size_t r = 0; r < serial.size(); ++r)
            if (!same_record(serial[r].record, parallel[r].record))
                return {"threads", CheckVerdict::fail,
                        "run " + std::to_string(r) + " differs when runs execute at once on " +
                            std::to_string(arena.max_concurrency()) +
                            " threads (state shared between runs: a static or mutable member?)"};
        return {"threads", CheckVerdict::pass,
                std::to_string(serial.size()) + " runs one after another and at once on " +
                    std::to_string(arena.max_concurrency()) + " threads: the same records"};
    }

    const Optimizer& optimizer_;
    std::string algorithm_spec_;
    const Problem& problem_;
    std::string problem_spec_;
    PluginCheckOptions options_;
};

// --- problems

CheckResult description(const Problem& problem) {
    try {
        if (problem.dimension() <= 0)
            return {"description", CheckVerdict::fail, "dimension " + std::to_string(problem.dimension())};
        problem.bounds().validate(problem.name());
        if (problem.bounds().dimension() != problem.dimension())
            return {"description", CheckVerdict::fail,
                    "the box has " + std::to_string(problem.bounds().dimension()) +
                        " dimensions, the problem " + std::to_string(problem.dimension())};
        const auto names = problem.parameter_names();
        if (!names.empty() && static_cast<Eigen::Index>(names.size()) != problem.dimension())
            return {"description", CheckVerdict::fail,
                    std::to_string(names.size()) + " parameter names for " +
                        std::to_string(problem.dimension()) + " dimensions"};
    } catch (const std::exception& e) {
        return {"description", CheckVerdict::fail, e.what()};
    }
    return {"description", CheckVerdict::pass,
            std::to_string(problem.dimension()) + " dimensions, a valid box" +
                (problem.known_optimum() ? ", a known optimum" : ", no known optimum")};
}

// The known optimum, where declared: its x in the box, and f there equal to the f declared.
CheckResult known_optimum(const Problem& problem) {
    const auto optimum = problem.known_optimum();
    if (!optimum || !optimum->x)
        return {"optimum", CheckVerdict::pass,
                optimum ? "f* declared without x*: not checked" : "none declared"};
    const Eigen::VectorXd& x = *optimum->x;
    if (x.size() != problem.dimension() || !problem.bounds().contains(x))
        return {"optimum", CheckVerdict::fail, "x* is not a point of the box"};
    const double f = problem.evaluate(x);
    const double tolerance = 1e-9 * std::max(1.0, std::abs(optimum->f));
    if (!(std::abs(f - optimum->f) <= tolerance))
        return {"optimum", CheckVerdict::fail, "f(x*) = " + number(f) + ", but f* = " + number(optimum->f)};
    return {"optimum", CheckVerdict::pass, "f(x*) = f* = " + number(optimum->f)};
}

std::vector<double> values_at(const Problem& problem, const std::vector<Eigen::VectorXd>& points,
                              int threads) {
    std::vector<double> f(points.size());
    if (threads <= 1) {
        for (std::size_t i = 0; i < points.size(); ++i)
            f[i] = problem.evaluate(points[i]);
        return f;
    }
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, points.size(),
                          [&](std::size_t i) { f[i] = problem.evaluate(points[i]); });
    });
    return f;
}

CheckResult values(const Problem& problem, const std::vector<double>& f) {
    const auto optimum = problem.known_optimum();
    std::size_t infinite = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        if (std::isnan(f[i]) || f[i] == -std::numeric_limits<double>::infinity())
            return {"values", CheckVerdict::fail,
                    "random point " + std::to_string(i) + ": f = " + number(f[i])};
        if (optimum && f[i] < optimum->f - 1e-9 * std::max(1.0, std::abs(optimum->f)))
            return {"values", CheckVerdict::fail,
                    "random point " + std::to_string(i) + ": f = " + number(f[i]) +
                        " is below f* = " + number(optimum->f)};
        infinite += std::isinf(f[i]) ? 1U : 0U;
    }
    const auto [low, high] = std::minmax_element(f.begin(), f.end());
    return {"values", infinite == f.size() ? CheckVerdict::warn : CheckVerdict::pass,
            std::to_string(f.size()) + " random points: f in [" + number(*low) + ", " + number(*high) + "]" +
                (infinite > 0 ? ", " + std::to_string(infinite) + " of them +inf" : "")};
}

// Microseconds per evaluation of `evaluate_all` (which evaluates every point once), repeated for
// at least 0.1 s so that the clock's resolution does not matter.
template <class EvaluateAll>
double microseconds_per_evaluation(std::size_t points, const EvaluateAll& evaluate_all) {
    using clock = std::chrono::steady_clock;
    std::size_t evaluations = 0;
    const auto start = clock::now();
    do {
        evaluate_all();
        evaluations += points;
    } while (clock::now() - start < std::chrono::milliseconds(100));
    return std::chrono::duration<double, std::micro>(clock::now() - start).count() /
           static_cast<double>(evaluations);
}

CheckResult cost(const Problem& problem, const std::vector<Eigen::VectorXd>& points) {
    std::vector<double> f(points.size());
    char text[160];
    int length = std::snprintf(text, sizeof text, "%.3g us per evaluation, one point a call",
                               microseconds_per_evaluation(points.size(), [&] {
                                   for (std::size_t i = 0; i < points.size(); ++i)
                                       f[i] = problem.evaluate(points[i]);
                               }));
    if (problem.batch_evaluation()) // an external program: one message for many points
        std::snprintf(text + length, sizeof text - static_cast<std::size_t>(length),
                      "; %.3g us with %zu points a call",
                      microseconds_per_evaluation(points.size(), [&] { problem.evaluate_many(points, f); }),
                      points.size());
    return {"cost", CheckVerdict::pass, std::string(text) + " (one thread)"};
}

} // namespace

const char* to_string(CheckVerdict verdict) {
    switch (verdict) {
    case CheckVerdict::pass:
        return "pass";
    case CheckVerdict::warn:
        return "warn";
    case CheckVerdict::fail:
        return "FAIL";
    }
    return "?";
}

std::vector<CheckResult> check_optimizer(const Optimizer& optimizer, const std::string& algorithm_spec,
                                         const Problem& problem, const std::string& problem_spec,
                                         const PluginCheckOptions& options) {
    return OptimizerCheck(optimizer, algorithm_spec, problem, problem_spec, options).run();
}

std::vector<CheckResult> check_problem(const Problem& problem, const PluginCheckOptions& options) {
    std::vector<CheckResult> results{description(problem)};
    if (results.back().verdict == CheckVerdict::fail)
        return results;
    try {
        results.push_back(known_optimum(problem));
        Rng rng(options.seed);
        std::vector<Eigen::VectorXd> points;
        for (std::int64_t i = 0; i < options.points; ++i)
            points.push_back(uniform_point(problem.bounds(), rng));
        const std::vector<double> f = values_at(problem, points, 1);
        results.push_back(values(problem, f));
        const bool repeatable = std::equal(f.begin(), f.end(), values_at(problem, points, 1).begin(),
                                           [](double a, double b) { return same_bits(a, b); });
        results.push_back({"same point", repeatable ? CheckVerdict::pass : CheckVerdict::fail,
                           repeatable ? "every random point again: the same value, bit for bit"
                                      : "a point evaluated twice gave two values (hidden state?)"});
        const int threads = std::max(2, options.threads);
        const bool thread_safe = std::equal(f.begin(), f.end(), values_at(problem, points, threads).begin(),
                                            [](double a, double b) { return same_bits(a, b); });
        results.push_back({"threads", thread_safe ? CheckVerdict::pass : CheckVerdict::fail,
                           thread_safe ? "the same values on " + std::to_string(threads) + " threads at once"
                                       : "values differ on " + std::to_string(threads) +
                                             " threads at once: evaluate() is not thread-safe"});
        results.push_back(cost(problem, points));
    } catch (const std::exception& e) {
        results.push_back({"evaluate", CheckVerdict::fail, e.what()});
    }
    return results;
}

} // namespace mhb
