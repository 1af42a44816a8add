// The counted, budgeted view of a Problem — the only way an optimiser sees one (the habit of
// pagmo's problem::fitness: count in the wrapper, not in the plug-in). It
//   - repairs out-of-bounds candidates by the policy the optimiser declares (clamp by default),
//   - counts every evaluation and enforces the budget exactly,
//   - keeps the best-so-far, and
//   - tells its TraceRecorder (problems/trace_recorder.hpp) of every evaluation and iteration,
//     which keeps best-so-far at the end of every iteration, on a fixed log-spaced grid of
//     evaluation counts shared by every run, and at every strict improvement.
//
// Budget enforcement: once the budget is spent, evaluate() throws BudgetExhausted instead of
// evaluating. Optimisers loop `while (!objective.exhausted())`, and an evaluation asked for in
// the middle of an iteration past the budget unwinds cleanly to run_to_budget() (see
// algorithms/optimizer.hpp). This makes every optimiser's count exact without a check after
// every evaluation in every inner loop.
//
// Parallel evaluation (evaluate_batch): a population whose points do not depend on each other's
// f can be handed over at once. The problem's values are then computed in parallel when the
// problem says one evaluation is expensive (Problem::parallel_evaluation), and all the
// bookkeeping above is done afterwards, in index order, so that the result is that of the same
// evaluate() calls one after another, bit for bit, whatever the number of threads.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "problems/problem.hpp"
#include "problems/trace_recorder.hpp"

namespace mhb {

struct Budget {
    std::optional<std::int64_t> max_evaluations;
    std::optional<std::int64_t> max_iterations;
    // Stop once best - f* <= target_error (needs a known optimum); the evaluations it took are kept.
    std::optional<double> target_error;

    // Throws std::invalid_argument unless at least one of evaluations/iterations is set and positive.
    void validate() const;
};

// How a candidate outside the box is brought back in.
enum class BoundPolicy {
    clamp,   // to the nearest face (the paper's choice)
    reflect, // mirrored at the violated face (repeatedly, for far-out points)
    none,    // evaluated as is (for optimisers that keep to the box themselves)
};

const char* to_string(BoundPolicy policy);

// Thrown by Objective::evaluate when the budget is already spent.
struct BudgetExhausted {};

struct ObjectiveOptions {
    bool record_best_x = false; // keep best x at every iteration (parameter trajectories)
};

class Objective {
public:
    Objective(const Problem& problem, Budget budget, BoundPolicy policy = BoundPolicy::clamp,
              ObjectiveOptions options = {});

    [[nodiscard]] Eigen::Index dimension() const { return dimension_; }
    [[nodiscard]] const Box& bounds() const { return box_; }
    [[nodiscard]] BoundPolicy bound_policy() const { return policy_; }

    // Repairs x in place (so the optimiser keeps the point actually evaluated), evaluates it,
    // counts it and updates the best-so-far. Throws BudgetExhausted if the budget is spent,
    // std::logic_error on a wrong size, std::runtime_error if the problem returns NaN, or -inf
    // where its known minimum is finite (+inf is a legal value: the worst).
    double evaluate(Eigen::VectorXd& x);
    void repair(Eigen::VectorXd& x) const;

    // f[i] = evaluate(x[i]) for i = 0, 1, ... in index order, with every effect of those calls and
    // nothing else: the same repairs in place, counts, best-so-far, checkpoints and target, and
    // the same exception at the same index (BudgetExhausted, a wrong size, NaN or -inf, or one
    // the problem throws), after which the remaining x are left as given and their f unset.
    // When problem.parallel_evaluation() is true and more than one point fits in the budget,
    // the values of those points (never more: an evaluation may cost a simulation) are computed
    // in parallel with oneTBB; when problem.batch_evaluation() is true they are handed to
    // problem.evaluate_many() in one call (a failure there is the first point's); otherwise this
    // is the plain loop. Throws std::logic_error unless
    // f.size() == x.size().
    void evaluate_batch(std::span<Eigen::VectorXd> x, std::span<double> f);

    // Call once after the initial population is evaluated (records iteration 0), and at the end
    // of every iteration (counts it against max_iterations and records it).
    void initialised();
    void end_iteration();

    [[nodiscard]] bool exhausted() const {
        return evaluations_ >= evaluation_limit_ || iterations_ >= iteration_limit_ ||
               evaluations_to_target_.has_value();
    }
    [[nodiscard]] std::int64_t evaluations() const { return evaluations_; }
    [[nodiscard]] std::int64_t iterations() const { return iterations_; }
    // Evaluations left before the evaluation budget is spent (max int64 without one).
    [[nodiscard]] std::int64_t remaining_evaluations() const;
    [[nodiscard]] const Budget& budget() const { return budget_; }

    [[nodiscard]] double best_f() const { return best_f_; }
    [[nodiscard]] const Eigen::VectorXd& best_x() const { return best_x_; }
    [[nodiscard]] std::optional<std::int64_t> evaluations_to_target() const { return evaluations_to_target_; }

    // What the recorder kept (see trace_recorder.hpp); the two traces below are shorthands.
    [[nodiscard]] const TraceRecorder& recorder() const { return recorder_; }
    [[nodiscard]] const std::vector<IterationPoint>& iteration_trace() const {
        return recorder_.iteration_trace();
    }
    [[nodiscard]] const std::vector<CheckpointPoint>& checkpoint_trace() const {
        return recorder_.checkpoint_trace();
    }

    // Closes the trace: the final evaluation count becomes the last checkpoint. Idempotent.
    void finish();

private:
    // The checks evaluate() makes before it evaluates (a wrong size, a spent budget), and the
    // bookkeeping it does once f is known; evaluate_batch() runs the two around parallel values.
    void check_before_evaluation(const Eigen::VectorXd& x) const;
    double account(const Eigen::VectorXd& x, double f);
    void record_iteration();

    const Problem& problem_;
    Budget budget_;
    BoundPolicy policy_;
    std::optional<double> f_opt_;
    // Read at every evaluation, so kept here rather than asked of the problem (a virtual call) or
    // unpacked from the budget's optionals each time: the Objective's own cost per evaluation is
    // a few nanoseconds (BENCHMARKS.md).
    Eigen::Index dimension_;
    const Box& box_;
    std::int64_t evaluation_limit_; // max int64 without an evaluation budget
    std::int64_t iteration_limit_;  // likewise
    bool minus_infinity_is_bad_;    // -inf is an error where the known minimum is finite
    std::int64_t evaluations_ = 0;
    std::int64_t iterations_ = 0;
    double best_f_ = std::numeric_limits<double>::infinity();
    Eigen::VectorXd best_x_;
    std::optional<std::int64_t> evaluations_to_target_;
    TraceRecorder recorder_;
};

} // namespace mhb
