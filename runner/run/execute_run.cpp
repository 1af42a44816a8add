#include "runner/run/execute_run.hpp"

#include <exception>
#include <memory>
#include <new>
#include <optional>

#include "problems/core/rng.hpp"

namespace mhb {
namespace {

std::vector<double> to_vector(const Eigen::VectorXd& x) {
    return {x.data(), x.data() + x.size()};
}

// The finished run's results, as the Objective recorded them.
void fill_from_objective(const Objective& objective, RunRecord& record) {
    record.best_f = objective.best_f();
    record.best_x = to_vector(objective.best_x());
    record.evaluations = objective.evaluations();
    record.iterations = objective.iterations();
    record.evaluations_to_target = objective.evaluations_to_target();
    for (const auto& p : objective.iteration_trace())
        record.curve.push_back({p.iteration, p.evaluations, p.best_f, to_vector(p.best_x)});
    for (const auto& c : objective.checkpoint_trace())
        record.checkpoints.push_back({c.evaluations, c.best_f});
    ImprovementTrace& improvements = record.improvements.emplace();
    improvements.points.reserve(objective.recorder().improvements().size());
    for (const auto& i : objective.recorder().improvements())
        improvements.points.push_back({i.evaluations, i.best_f});
    improvements.last_f = objective.recorder().last_f();
}

} // namespace

RunRecord execute_run(const RunRequest& request) {
    RunRecord record;
    record.run_id = request.run_id;
    record.algorithm = request.algorithm_spec;
    record.problem = request.problem_spec;
    record.run_index = request.run_index;
    record.budget = request.budget_text;
    record.seed = request.seed;
    // A problem random per run (f0) gives this run an instance of its own (ARCHITECTURE.md 4.1);
    // declared before the Objective that refers to it, so that it outlives it.
    std::unique_ptr<Problem> own_instance;
    // Outside the try, so that a failed run still records the evaluations it spent.
    std::optional<Objective> objective;
    // Everything that asks the problem or the optimiser anything is inside the try: a component
    // that throws fails its own run, never the study.
    try {
        own_instance = request.problem->for_run(record.seed);
        const Problem& problem = own_instance ? *own_instance : *request.problem;
        record.parameter_names = problem.parameter_names();
        if (const auto truth = problem.true_parameters())
            record.true_parameters = to_vector(*truth);
        if (const auto optimum = problem.known_optimum()) {
            record.f_opt = optimum->f;
            if (optimum->x)
                record.x_opt = to_vector(*optimum->x);
        }
        ObjectiveOptions options;
        options.record_best_x = !record.parameter_names.empty();
        objective.emplace(problem, request.budget, request.optimizer->bound_policy(), options);
        Rng rng(record.seed);
        run_to_budget(*request.optimizer, *objective, rng);
        fill_from_objective(*objective, record);
        if (objective->evaluations() == 0) {
            record.ok = false;
            record.message = "the optimiser made no evaluation";
        }
    } catch (const std::bad_alloc&) {
        record.ok = false;
        record.message = "the run ran out of memory (std::bad_alloc): lower the population or the dimension";
    } catch (const std::exception& e) {
        record.ok = false;
        record.message = e.what();
    } catch (...) {
        record.ok = false;
        record.message = "the run threw something that is not a std::exception";
    }
    if (!record.ok) {
        // What the failed run spent counts against it (a retry spends it again); its curves and
        // best point are no result.
        if (objective) {
            record.evaluations = objective->evaluations();
            record.iterations = objective->iterations();
        }
        record.curve.clear();
        record.checkpoints.clear();
        record.improvements.reset();
    }
    return record;
}

} // namespace mhb
