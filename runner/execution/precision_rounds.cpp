#include "runner/execution/precision_rounds.hpp"

#include <algorithm>
#include <mutex>
#include <stdexcept>

#include "results/analysis/run_precision.hpp"
#include "results/store/study_writer.hpp"

namespace mhb {

namespace {

// Run ids of one cell: ((budget * problems + problem) * algorithms + algorithm) * runs + index.
struct CellIds {
    std::int64_t first = 0;

    [[nodiscard]] std::int64_t id(std::int64_t index) const { return first + index; }
};

// The compared values of a cell's runs 0, 1, ... as far as they are known without a gap.
std::vector<double> known_prefix(const CellIds& cell, std::int64_t most,
                                 const std::map<std::int64_t, double>& values) {
    std::vector<double> out;
    for (std::int64_t r = 0; r < most; ++r) {
        const auto found = values.find(cell.id(r));
        if (found == values.end())
            break;
        out.push_back(found->second);
    }
    return out;
}

void add_runs(const CellIds& cell, std::int64_t count, std::vector<std::int64_t>& wanted) {
    for (std::int64_t r = 0; r < count; ++r)
        wanted.push_back(cell.id(r));
}

} // namespace

PrecisionPlan plan_precision_runs(const PreparedStudy& study, const std::map<std::int64_t, double>& values) {
    if (!study.study.by_precision)
        throw std::logic_error("plan_precision_runs: the study has a fixed number of runs");
    const PrecisionRule& rule = *study.study.by_precision;
    const bool paired = study.study.seeds == SeedMode::common;
    const auto algorithms = static_cast<std::int64_t>(study.algorithms.size());
    const auto problems = static_cast<std::int64_t>(study.problems.size());
    const auto budgets = static_cast<std::int64_t>(study.study.budgets.size());
    std::vector<std::string> specs;
    for (const PreparedAlgorithm& a : study.algorithms)
        specs.push_back(a.info.spec);
    const auto reference = static_cast<std::int64_t>(default_reference_index(specs));

    PrecisionPlan plan;
    for (std::int64_t b = 0; b < budgets; ++b)
        for (std::int64_t p = 0; p < problems; ++p) {
            const auto cell = [&](std::int64_t a) {
                return CellIds{((b * problems + p) * algorithms + a) * study.study.runs};
            };
            const std::vector<double> reference_values = known_prefix(cell(reference), rule.max, values);
            std::int64_t reference_needs = 0;
            for (std::int64_t a = 0; a < algorithms; ++a) {
                if (a == reference && algorithms > 1)
                    continue;
                const std::vector<double> own =
                    a == reference ? reference_values : known_prefix(cell(a), rule.max, values);
                const CellPrecision point =
                    stopping_point(own, a == reference ? nullptr : &reference_values, paired, rule);
                plan.unsettled_cells += point.stop == PrecisionStop::needs_runs ? 1 : 0;
                reference_needs = std::max(reference_needs, point.runs);
                if (a != reference)
                    add_runs(cell(a), point.runs, plan.wanted);
            }
            add_runs(cell(reference), reference_needs, plan.wanted);
        }
    std::sort(plan.wanted.begin(), plan.wanted.end());
    return plan;
}

RunnerOutcome run_study_by_precision(const PreparedStudy& study, StudyWriter& writer,
                                     const RunnerOptions& options, const PrecisionRoundHooks& hooks) {
    // What the store holds already (failed runs are not completed: they are computed again).
    std::map<std::int64_t, double> values;
    for (const std::int64_t id : writer.completed())
        if (id < study.run_count())
            if (const std::optional<RunRecord> record = writer.stored_run(id))
                values[id] = compared_value(*record);
    const std::map<std::int64_t, double> found_at_start = values;

    std::mutex values_mutex; // calls of on_run_finished are serialised, but stay safe
    RunnerOptions round = options;
    round.finish_writer = false;
    round.on_run_finished = [&](std::int64_t kept, std::int64_t total, const RunRecord& record) {
        {
            const std::lock_guard<std::mutex> lock(values_mutex);
            values[record.run_id] = compared_value(record);
        }
        if (options.on_run_finished)
            options.on_run_finished(kept, total, record);
    };
    RunnerOutcome outcome;
    for (int number = 1;; ++number) {
        PrecisionPlan plan;
        std::vector<std::int64_t> pending;
        try {
            plan = plan_precision_runs(study, values);
            for (const std::int64_t id : plan.wanted)
                if (values.count(id) == 0)
                    pending.push_back(id);
        } catch (...) {
            if (hooks.announce) // whoever waits for the next round must not wait for ever
                hooks.announce(false);
            throw;
        }
        if (hooks.announce)
            hooks.announce(!pending.empty());
        outcome.total = static_cast<std::int64_t>(plan.wanted.size());
        outcome.resumed = static_cast<std::int64_t>(
            std::count_if(plan.wanted.begin(), plan.wanted.end(),
                          [&](std::int64_t id) { return found_at_start.count(id) != 0; }));
        if (pending.empty()) {
            if (plan.unsettled_cells != 0)
                throw std::logic_error("run_study_by_precision: cells ask for runs the plan does not list");
            outcome.kept = outcome.total;
            writer.render_only(plan.wanted);
            writer.finish();
            return outcome;
        }
        if (hooks.on_round)
            hooks.on_round({number, pending, plan.unsettled_cells});
        round.run_ids = pending;
        const RunnerOutcome done = hooks.run ? hooks.run(round) : run_study(study, writer, round);
        if (done.interrupted) {
            outcome.kept = outcome.total - static_cast<std::int64_t>(pending.size()) + done.kept;
            outcome.interrupted = true;
            return outcome;
        }
    }
}

} // namespace mhb
