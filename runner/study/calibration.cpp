#include "runner/study/calibration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <thread>

#include "problems/core/rng.hpp"
#include "runner/run/execute_run.hpp"

namespace mhb {

namespace {

// How much shorter a calibration run is than the run it stands for, and its floor.
constexpr std::int64_t calibration_divisor = 50;
constexpr std::int64_t calibration_min_evaluations = 2000;
constexpr std::int64_t calibration_min_iterations = 3;

// The problems the calibration runs on, each with the number of the study's problems it stands
// for: per dimension, up to `per_dimension` of them spread over that dimension's problems (first
// and last included), because time per evaluation grows with the dimension.
std::vector<std::pair<std::size_t, double>> calibration_sample(const PreparedStudy& study,
                                                               std::size_t per_dimension) {
    std::map<Eigen::Index, std::vector<std::size_t>> by_dimension;
    for (std::size_t p = 0; p < study.problems.size(); ++p)
        by_dimension[study.problems[p].problem->dimension()].push_back(p);
    std::vector<std::pair<std::size_t, double>> sample;
    for (const auto& [dimension, group] : by_dimension) {
        const std::size_t count = std::min(group.size(), std::max<std::size_t>(per_dimension, 1));
        const double share = static_cast<double>(group.size()) / static_cast<double>(count);
        for (std::size_t i = 0; i < count; ++i)
            sample.emplace_back(group[count == 1 ? 0 : i * (group.size() - 1) / (count - 1)], share);
    }
    return sample;
}

} // namespace

double StudyEstimate::evaluations() const {
    double total = 0;
    for (const auto& b : budgets)
        total += b.evaluations;
    return total;
}

double StudyEstimate::cpu_seconds() const {
    double total = 0;
    for (const auto& b : budgets)
        total += b.cpu_seconds;
    return total;
}

RunRecord short_run(RunRequest request, std::int64_t max_evaluations) {
    request.budget.max_iterations = std::min<std::int64_t>(request.budget.max_iterations.value_or(3), 3);
    request.budget.max_evaluations =
        std::min<std::int64_t>(request.budget.max_evaluations.value_or(max_evaluations), max_evaluations);
    request.budget.target_error.reset();
    return execute_run(request);
}

RunRecord calibration_run(RunRequest request) {
    Budget& budget = request.budget;
    if (budget.max_evaluations)
        budget.max_evaluations =
            std::min(*budget.max_evaluations,
                     std::max(*budget.max_evaluations / calibration_divisor, calibration_min_evaluations));
    if (budget.max_iterations)
        budget.max_iterations =
            std::min(*budget.max_iterations,
                     std::max(*budget.max_iterations / calibration_divisor, calibration_min_iterations));
    budget.target_error.reset();
    return execute_run(request);
}

double extrapolated_evaluations(const RunRecord& short_run, const Budget& budget) {
    // Evaluations of the initialisation (iteration 0) and per iteration after it.
    const double initial =
        short_run.curve.empty() ? 0.0 : static_cast<double>(short_run.curve.front().evaluations);
    const double per_iteration = short_run.iterations > 0
                                     ? (static_cast<double>(short_run.evaluations) - initial) /
                                           static_cast<double>(short_run.iterations)
                                     : static_cast<double>(short_run.evaluations);
    double full = budget.max_evaluations ? static_cast<double>(*budget.max_evaluations) : 1e300;
    if (budget.max_iterations)
        full = std::min(full, initial + per_iteration * static_cast<double>(*budget.max_iterations));
    return full;
}

namespace {

// One calibration run of a (budget, algorithm, sampled problem), extrapolated to one full run.
struct Calibration {
    std::size_t budget, algorithm;
    double share; // how many of the study's problems it stands for
    std::int64_t run_id;
    double full_evaluations = 0, seconds = 0; // 0 when the run failed
};

// Every (budget, algorithm, sampled problem) of the study, run on `threads` threads as the study
// will be: each run's time is then measured under the same sharing of the machine.
std::vector<Calibration> run_calibrations(const PreparedStudy& study,
                                          const std::vector<std::pair<std::size_t, double>>& sample,
                                          int threads) {
    const std::size_t algorithms = study.algorithms.size();
    const std::size_t problems = study.problems.size();
    std::vector<Calibration> calibrations;
    for (std::size_t b = 0; b < study.study.budgets.size(); ++b)
        for (std::size_t a = 0; a < algorithms; ++a)
            for (const auto& [p, share] : sample)
                calibrations.push_back(
                    {b, a, share,
                     static_cast<std::int64_t>(((b * problems + p) * algorithms + a)) * study.study.runs});
    tbb::task_arena(std::max(threads, 1)).execute([&] {
        tbb::parallel_for(std::size_t{0}, calibrations.size(), [&](std::size_t i) {
            Calibration& c = calibrations[i];
            const RunRequest request = study.request(c.run_id);
            const auto started = std::chrono::steady_clock::now();
            const RunRecord record = calibration_run(request);
            const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;
            if (!record.ok || record.evaluations <= 0)
                return;
            c.full_evaluations = extrapolated_evaluations(record, request.budget); // at its dimension
            c.seconds = c.full_evaluations * wall.count() / static_cast<double>(record.evaluations);
        });
    });
    return calibrations;
}

} // namespace

StudyEstimate estimate_study(const PreparedStudy& study, int threads, std::size_t problems_per_dimension) {
    const auto calibration_started = std::chrono::steady_clock::now();
    const std::size_t algorithms = study.algorithms.size();
    const double runs = static_cast<double>(study.study.runs);
    const std::vector<Calibration> calibrations =
        run_calibrations(study, calibration_sample(study, problems_per_dimension), threads);

    // Summed in a fixed order, whatever order the runs finished in.
    StudyEstimate estimate;
    estimate.calibration_runs = static_cast<std::int64_t>(calibrations.size());
    estimate.budgets.resize(study.study.budgets.size());
    estimate.algorithm_seconds.assign(algorithms, 0.0);
    for (const Calibration& c : calibrations) {
        BudgetEstimate& out = estimate.budgets[c.budget];
        out.evaluations += c.full_evaluations * c.share * runs;
        out.cpu_seconds += c.seconds * c.share * runs;
        estimate.algorithm_seconds[c.algorithm] += c.seconds * c.share * runs;
    }
    for (std::size_t b = 0; b < estimate.budgets.size(); ++b) {
        const StudyBudget& budget = study.study.budgets[b];
        BudgetEstimate& out = estimate.budgets[b];
        out.exact = (budget.max_evaluations || budget.evaluations_by_dimension) && !budget.max_iterations &&
                    !budget.target_error && !budget.relative_target;
        if (out.exact) { // every run spends its budget: the count, not a sample's
            out.evaluations = 0;
            for (std::size_t p = 0; p < study.problems.size(); ++p)
                out.evaluations += static_cast<double>(*study.budget_for(b, p).max_evaluations) *
                                   static_cast<double>(algorithms) * runs;
        }
    }
    estimate.calibration_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - calibration_started).count();
    return estimate;
}

namespace {

// CPU seconds of one figure of each kind, PDF and PNG, measured on the project's 2-vCPU VM (AMD
// EPYC, Debian 12, matplotlib 3.6) from the paper, ablation and cec2017-smoke presets' reports with
// the script's own jobs (`p.plan_folder(dir)`, then each job's draw and both savefigs, timed by
// time.process_time, MHB_PLOT_WORKERS=1), each kind's median per panel; a panel's cost grows a little
// with the algorithms it draws. Kinds drawn per problem are panels of one figure (plot_study.py's
// MOST_PANELS), so these are per panel. On another machine they are scaled by machine_speed_ratio().
constexpr double figure_startup_seconds = 0.7; // python3, matplotlib and the warm-up figure
constexpr double convergence_seconds = 0.09;   // a panel; + per algorithm:
constexpr double convergence_per_algorithm = 0.002;
constexpr double parameters_seconds = 0.245; // four panels; + per algorithm:
constexpr double parameters_per_algorithm = 0.015;
constexpr double final_values_seconds = 0.04; // a panel; + per algorithm:
constexpr double final_values_per_algorithm = 0.01;
constexpr double ecdf_seconds = 0.14;           // the problems pooled
constexpr double ranks_seconds = 0.07;          // critical difference, relative gaps
constexpr double effects_seconds = 0.16;        // each of the three figures of a factorial design
constexpr double bayesian_panel_seconds = 0.06; // a simplex panel (an algorithm against the reference)
// The tables and curve data: measured `mhbench report --no-figures` of the paper (60 runs) and
// ablation (960 runs) presets.
constexpr double tables_seconds_base = 0.05;
constexpr double tables_seconds_per_run = 0.0004;
// The figures' reference work (reference_work_seconds) took this long where the costs above were
// measured: its best of three, on the same VM, idle apart from it.
constexpr double reference_work_seconds_there = 0.0063;
// As many figures of one kind as plot_study.py draws as panels of one figure (its MOST_PANELS).
constexpr std::size_t most_panels = 6;

// A fixed piece of scalar work like a figure script's (a Rastrigin sum over points of a fixed
// stream, a few milliseconds), timed here: the best of three, since a busy machine only slows it.
double reference_work_seconds() {
    double best = 1e300;
    for (int repeat = 0; repeat < 3; ++repeat) {
        Rng rng(1);
        volatile double sink = 0; // the work must not be optimised away
        const auto started = std::chrono::steady_clock::now();
        double sum = 0;
        for (int i = 0; i < (1 << 18); ++i) {
            const double x = rng.uniform(-5.12, 5.12);
            sum += x * x - 10.0 * std::cos(2.0 * 3.141592653589793 * x) + 10.0;
        }
        sink = sum;
        (void)sink;
        best =
            std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    }
    return best;
}

// Whether the algorithms look like a 2^k on/off grid (labels such as itlbo[T+S-O+]): the report
// then analyses it as a factorial design, with three figures.
bool factorial_grid(const PreparedStudy& study) {
    if (study.algorithms.size() < 4)
        return false;
    for (const auto& a : study.algorithms)
        if (a.info.label.find('[') == std::string::npos)
            return false;
    return true;
}

// The Bayesian simplex figures of one budget (results/analysis/bayesian_comparisons.hpp): one for
// the test on all problems' medians (two or more problems, all with f*), else one per problem where
// the runs pair by seed; a panel per algorithm but the reference.
std::int64_t bayesian_simplex_figures(const PreparedStudy& study, std::size_t known) {
    const std::size_t problems = study.problems.size();
    if (study.algorithms.size() < 2)
        return 0;
    if (problems >= 2 && known == problems)
        return 1;
    return study.study.seeds == SeedMode::common ? static_cast<std::int64_t>(problems) : 0;
}

} // namespace

std::int64_t ReportEstimate::figure_count() const {
    std::int64_t total = 0;
    for (const auto& kind : figures)
        total += kind.second;
    return total;
}

ReportEstimate estimate_report(const PreparedStudy& study, bool figures) {
    ReportEstimate estimate;
    estimate.tables_seconds =
        tables_seconds_base + tables_seconds_per_run * static_cast<double>(study.run_count());
    if (!figures)
        return estimate;
    const double algorithms = static_cast<double>(study.algorithms.size());
    const std::size_t problems = study.problems.size();
    // Figures of a kind drawn per problem: one with a panel each for 2 to most_panels problems.
    const auto figures_of = [](std::size_t count) {
        return static_cast<std::int64_t>(count >= 2 && count <= most_panels ? 1 : count);
    };
    std::size_t known = 0, identified = 0;
    for (const auto& p : study.problems) {
        known += p.problem->known_optimum().has_value() ? 1U : 0U;
        identified += p.problem->parameter_names().empty() ? 0U : 1U;
    }
    std::int64_t convergence = 0, parameters = 0, finals = 0, ecdf = 0, ranks = 0, effects = 0, bayesian = 0;
    double panels = 0; // of the kinds drawn per problem, weighted by their cost
    for (const StudyBudget& budget : study.study.budgets) {
        const std::int64_t convergence_kinds =
            budget.max_iterations ? 2 : 1; // by iteration where iterations count
        convergence += convergence_kinds * figures_of(problems);
        panels +=
            static_cast<double>(convergence_kinds) * static_cast<double>(problems) *
                (convergence_seconds + convergence_per_algorithm * algorithms) +
            static_cast<double>(problems) * (final_values_seconds + final_values_per_algorithm * algorithms);
        parameters += static_cast<std::int64_t>(identified);
        finals += figures_of(problems);
        // Pooled over the problems: COCO's targets where f* is known (two problems at least), and
        // the study's own target when it has one.
        ecdf +=
            (known >= 2 ? 1 : 0) + (known >= 1 && (budget.target_error || budget.relative_target) ? 1 : 0);
        ranks += problems >= 2 && study.algorithms.size() >= 2 ? 1 : 0;
        effects += factorial_grid(study) ? 3 : 0;
        bayesian += bayesian_simplex_figures(study, known);
    }
    estimate.figures = {
        {"convergence", convergence},   {"parameters", parameters}, {"final_values", finals}, {"ecdf", ecdf},
        {"critical_difference", ranks}, {"effects", effects},       {"bayesian", bayesian}};
    const double cpu =
        panels +
        static_cast<double>(parameters) * (parameters_seconds + parameters_per_algorithm * algorithms) +
        static_cast<double>(ecdf) * ecdf_seconds + static_cast<double>(ranks) * ranks_seconds +
        static_cast<double>(effects) * effects_seconds +
        static_cast<double>(bayesian) * (algorithms - 1.0) * bayesian_panel_seconds;
    // Measured on the reference VM: scaled by how much slower or faster this machine does the same
    // work, as the runs' estimate times the study's own runs here.
    estimate.speed_ratio = reference_work_seconds() / reference_work_seconds_there;
    // The script draws on as many workers as the process may use CPUs (plot_study.py).
    const double workers = std::max(1.0, static_cast<double>(std::thread::hardware_concurrency()));
    estimate.figures_seconds =
        estimate.speed_ratio *
        (figure_startup_seconds +
         cpu / std::min(workers, std::max(1.0, static_cast<double>(estimate.figure_count()))));
    return estimate;
}

} // namespace mhb
