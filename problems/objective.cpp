#include "problems/objective.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>
#include <stdexcept>
#include <string>

#include "problems/core/parameters.hpp"

namespace mhb {

void Budget::validate() const {
    if (!max_evaluations && !max_iterations)
        throw std::invalid_argument("budget: give a number of evaluations or of iterations");
    if (max_evaluations && *max_evaluations <= 0)
        throw std::invalid_argument("budget: evaluations = " + std::to_string(*max_evaluations) +
                                    " is outside [1, inf)");
    if (max_iterations && *max_iterations <= 0)
        throw std::invalid_argument("budget: iterations = " + std::to_string(*max_iterations) +
                                    " is outside [1, inf)");
    if (target_error && !(*target_error >= 0.0 && std::isfinite(*target_error)))
        throw std::invalid_argument("budget: target = " + format_real(*target_error) +
                                    " is outside [0, inf)");
}

const char* to_string(BoundPolicy policy) {
    switch (policy) {
    case BoundPolicy::clamp:
        return "clamp";
    case BoundPolicy::reflect:
        return "reflect";
    case BoundPolicy::none:
        return "none";
    }
    return "?";
}

namespace {

// A point as it is named in an error: every coordinate for small dimensions, the first few else.
std::string point_text(const Eigen::VectorXd& x) {
    std::string out = "(";
    const Eigen::Index shown = std::min<Eigen::Index>(x.size(), 6);
    for (Eigen::Index i = 0; i < shown; ++i)
        out += (i ? ", " : "") + format_real(x[i]);
    if (shown < x.size())
        out += ", ... " + std::to_string(x.size() - shown) + " more";
    return out + ")";
}

// The errors of evaluate(), built out of its way: it is in every optimiser's inner loop.
[[noreturn, gnu::cold]] void throw_wrong_size(const Problem& problem, Eigen::Index size) {
    throw std::logic_error("objective: point of dimension " + std::to_string(size) + " given to '" +
                           problem.name() + "' of dimension " + std::to_string(problem.dimension()));
}

[[noreturn, gnu::cold]] void throw_bad_value(const Problem& problem, double f, std::int64_t evaluation,
                                             const Eigen::VectorXd& x) {
    throw std::runtime_error("problem '" + problem.name() + "' returned " + (std::isnan(f) ? "NaN" : "-inf") +
                             " at evaluation " + std::to_string(evaluation) + ", x = " + point_text(x));
}

} // namespace

Objective::Objective(const Problem& problem, Budget budget, BoundPolicy policy, ObjectiveOptions options)
    : problem_(problem), budget_(budget), policy_(policy), dimension_(problem.dimension()),
      box_(problem.bounds()),
      evaluation_limit_(budget.max_evaluations.value_or(std::numeric_limits<std::int64_t>::max())),
      iteration_limit_(budget.max_iterations.value_or(std::numeric_limits<std::int64_t>::max())),
      recorder_(options.record_best_x) {
    budget_.validate();
    if (const auto opt = problem_.known_optimum())
        f_opt_ = opt->f;
    minus_infinity_is_bad_ = f_opt_ && std::isfinite(*f_opt_);
    if (budget_.target_error && !f_opt_)
        throw std::invalid_argument("budget: a target needs a problem with a known optimum; '" +
                                    problem_.name() + "' has none");
}

void Objective::repair(Eigen::VectorXd& x) const {
    const Box& box = box_;
    switch (policy_) {
    case BoundPolicy::clamp:
        x = x.cwiseMax(box.lower).cwiseMin(box.upper);
        break;
    case BoundPolicy::reflect:
        for (Eigen::Index i = 0; i < x.size(); ++i) {
            const double lo = box.lower[i];
            const double hi = box.upper[i];
            const double width = hi - lo;
            double v = x[i];
            if (v >= lo && v <= hi)
                continue;
            if (!std::isfinite(v)) {
                x[i] = v > 0 ? hi : lo;
                continue;
            }
            // Reflection is periodic with period 2*width.
            double t = std::fmod(v - lo, 2.0 * width);
            if (t < 0)
                t += 2.0 * width;
            x[i] = t <= width ? lo + t : hi - (t - width);
        }
        break;
    case BoundPolicy::none:
        break;
    }
}

void Objective::check_before_evaluation(const Eigen::VectorXd& x) const {
    if (x.size() != dimension_)
        throw_wrong_size(problem_, x.size());
    if (exhausted())
        throw BudgetExhausted{};
}

double Objective::account(const Eigen::VectorXd& x, double f) {
    // +inf is a legal value, the worst there is. NaN is never one; nor is -inf below a finite
    // known minimum. Either fails the run, naming the evaluation and the point.
    if (std::isnan(f) || (f == -std::numeric_limits<double>::infinity() && minus_infinity_is_bad_))
        [[unlikely]]
        throw_bad_value(problem_, f, evaluations_ + 1, x);
    ++evaluations_;
    const bool improved = f < best_f_;
    if (improved || best_x_.size() == 0) [[unlikely]] {
        best_f_ = f;
        best_x_ = x;
        // best_f changes only here, so the target is met here or never.
        if (f_opt_ && budget_.target_error && !evaluations_to_target_ &&
            best_f_ - *f_opt_ <= *budget_.target_error)
            evaluations_to_target_ = evaluations_;
    }
    recorder_.evaluated(evaluations_, f, best_f_, improved);
    return f;
}

double Objective::evaluate(Eigen::VectorXd& x) {
    check_before_evaluation(x);
    repair(x);
    return account(x, problem_.evaluate(x));
}

void Objective::evaluate_batch(std::span<Eigen::VectorXd> x, std::span<double> f) {
    if (f.size() != x.size())
        throw std::logic_error("objective: a batch of " + std::to_string(x.size()) + " points given " +
                               std::to_string(f.size()) + " places for their values");
    // The points evaluate() would reach: within the budget, and before the first of a wrong size.
    // Only these are computed ahead; a target reached or an error on the way may still stop the
    // bookkeeping earlier, and then some values computed are dropped (never counted).
    std::size_t ahead = 0;
    const bool batched = problem_.batch_evaluation();
    if ((batched || problem_.parallel_evaluation()) && x.size() > 1 && !exhausted()) {
        const auto room =
            static_cast<std::size_t>(std::min(remaining_evaluations(), static_cast<std::int64_t>(x.size())));
        while (ahead < room && x[ahead].size() == dimension_)
            ++ahead;
    }
    if (ahead < 2) {
        for (std::size_t i = 0; i < x.size(); ++i)
            f[i] = evaluate(x[i]);
        return;
    }

    // Repaired copies, so that a point the bookkeeping never reaches is left as it was given.
    // An exception of the problem is kept and rethrown at its index, as evaluate() would.
    std::vector<Eigen::VectorXd> repaired(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(ahead));
    std::vector<double> values(ahead);
    std::vector<std::exception_ptr> errors(ahead);
    if (batched) {
        // One call for the whole batch (one message to an external program). Its failure is
        // that of the first point: none of the batch is counted, as when evaluate() throws.
        try {
            for (auto& r : repaired)
                repair(r);
            problem_.evaluate_many(repaired, values);
        } catch (...) {
            errors[0] = std::current_exception();
        }
    } else {
        // Isolated: a thread waiting here helps with these points only, and never starts another
        // task of the caller's (another run of the study) in the middle of this one's iteration.
        tbb::this_task_arena::isolate([&] {
            tbb::parallel_for(
                tbb::blocked_range<std::size_t>(0, ahead, 1),
                [&](const tbb::blocked_range<std::size_t>& range) {
                    for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        try {
                            repair(repaired[i]);
                            values[i] = problem_.evaluate(repaired[i]);
                        } catch (...) {
                            errors[i] = std::current_exception();
                        }
                    }
                },
                tbb::simple_partitioner());
        });
    }

    for (std::size_t i = 0; i < x.size(); ++i) {
        if (i >= ahead) {
            f[i] = evaluate(x[i]); // throws: the budget is spent, or x[i] has a wrong size
            continue;
        }
        check_before_evaluation(x[i]);
        x[i] = repaired[i];
        if (errors[i])
            std::rethrow_exception(errors[i]);
        f[i] = account(x[i], values[i]);
    }
}

void Objective::initialised() {
    record_iteration();
}

void Objective::end_iteration() {
    ++iterations_;
    record_iteration();
}

void Objective::record_iteration() {
    recorder_.iteration_ended(iterations_, evaluations_, best_f_, best_x_);
}

std::int64_t Objective::remaining_evaluations() const {
    if (!budget_.max_evaluations)
        return std::numeric_limits<std::int64_t>::max();
    return std::max<std::int64_t>(0, *budget_.max_evaluations - evaluations_);
}

void Objective::finish() {
    recorder_.finish(evaluations_, best_f_);
}

} // namespace mhb
