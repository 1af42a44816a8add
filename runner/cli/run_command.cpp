// `mhbench run`: describe a study (options, a preset, or a study file), validate all of it,
// run it in parallel into a study directory, and print a short summary. Ctrl-C stops starting
// new runs, keeps the finished ones, and the same command resumes.
#include <algorithm>
#include <atomic>
#include <boost/program_options.hpp>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/core/spec.hpp"
#include "problems/core/text_excerpt.hpp"
#include "results/report/report.hpp"
#include "results/reporters/count_of.hpp"
#include "results/reporters/reporter_registry.hpp"
#include "results/store/csv.hpp"
#include "results/store/run_key.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_writer.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/format_option.hpp"
#include "runner/cli/parse_command_line.hpp"
#include "runner/cli/rope_option.hpp"
#include "runner/cli/run_options.hpp"
#include "runner/distribution/distributed.hpp"
#include "runner/distribution/shards.hpp"
#include "runner/execution/companion_files.hpp"
#include "runner/execution/context.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/execution/precision_rounds.hpp"
#include "runner/execution/progress.hpp"
#include "runner/execution/run_identity.hpp"
#include "runner/execution/study_lock.hpp"
#include "runner/plugins/components.hpp"
#include "runner/study/calibration.hpp"
#include "runner/study/dry_run.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"

namespace mhb::cli {
namespace po = boost::program_options;

namespace {

// Set by SIGINT/SIGTERM; read by the runner before each run starts. A lock-free atomic is safe
// to store from a signal handler.
std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_stop_signal(int) {
    stop_requested.store(true);
}

// Installs the stop handler for the lifetime of a study and restores the previous ones.
// SA_RESETHAND: a second Ctrl-C gets the default action and ends the process at once (the
// store is safe either way: a half-written block is dropped on resume).
class StopSignals {
public:
    StopSignals() {
        struct sigaction action {};
        action.sa_handler = on_stop_signal;
        sigemptyset(&action.sa_mask);
        action.sa_flags = static_cast<int>(SA_RESETHAND); // an unsigned constant in glibc
        sigaction(SIGINT, &action, &previous_int_);
        sigaction(SIGTERM, &action, &previous_term_);
    }
    ~StopSignals() {
        sigaction(SIGINT, &previous_int_, nullptr);
        sigaction(SIGTERM, &previous_term_, nullptr);
    }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

private:
    struct sigaction previous_int_ {};
    struct sigaction previous_term_ {};
};

// The summary on stdout (unless quiet) and, whatever quiet says, failed runs on stderr: how many,
// and the first messages. Returns the number of failed runs and the total.
std::pair<std::int64_t, std::int64_t> report_outcome(const StudySummary& summary,
                                                     const std::filesystem::path& dir,
                                                     const RunnerOutcome& outcome, double wall_seconds,
                                                     bool quiet) {
    const std::int64_t failed = summary.failed;
    const std::int64_t total = summary.runs;
    if (!quiet) {
        char line[256];
        std::snprintf(line, sizeof line, "%lld runs (%lld failed), %lld evaluations, %.3g s wall",
                      static_cast<long long>(total), static_cast<long long>(failed),
                      static_cast<long long>(summary.evaluations), wall_seconds);
        std::cout << "study finished: " << line;
        if (outcome.resumed > 0)
            std::cout << " (" << outcome.total - outcome.resumed << " run now, " << outcome.resumed
                      << " found in the store)";
        std::cout << "\nresults in " << dir.string() << '\n';
    }
    if (failed > 0) {
        std::cerr << "mhbench run: " << failed << " of " << total << " runs failed"
                  << (failed == total ? " (all of them)" : "") << "; each carries its message in "
                  << (dir / StudyFiles::runs).string()
                  << " (column 'message'), and the same command computes them again. The first:\n";
        for (const auto& r : summary.first_failures) {
            std::string message = r.message; // one line each, as runs.csv shows it
            std::replace(message.begin(), message.end(), '\n', ' ');
            std::cerr << "  run " << r.run_id << " (" << r.algorithm << " on " << r.problem << ", run "
                      << r.run_index << "): " << message << '\n';
        }
    }
    return {failed, total};
}

// What `mhbench run` is told beside the study: checked with it, so that every error is said at once.
struct RunSettings {
    int threads = 0; // 0: all hardware threads
    std::optional<ShardSpec> shard;
    std::set<std::string> formats; // of the report's tables (--format)
};

RunSettings check_run_settings(const po::variables_map& vm, std::vector<std::string>& errors) {
    RunSettings settings;
    if (!(vm["progress-interval"].as<double>() > 0.0))
        errors.push_back("progress-interval = " + format_real(vm["progress-interval"].as<double>()) +
                         " is outside (0, inf)");
    if (vm.count("threads") != 0) {
        const std::string& text = vm["threads"].as<std::string>();
        long long value = 0;
        // Read as text so that a malformed or huge value gets our message, not Boost's "is invalid".
        if (!parse_integer(text, value))
            errors.push_back("threads = " + value_excerpt(text) + " " + integer_refusal(text, 1, 100000));
        else if (value < 1)
            errors.push_back("threads = " + std::to_string(value) + " is outside [1, inf)");
        else
            settings.threads = static_cast<int>(std::min<long long>(value, 100000));
    }
    if (vm.count("shard") != 0) {
        try {
            settings.shard = parse_shard(vm["shard"].as<std::string>());
        } catch (const std::invalid_argument& e) {
            errors.emplace_back(e.what());
        }
    }
    // Checked now, not when the report is built after the whole study has run.
    settings.formats = parse_format_option(vm["format"].as<std::string>());
    if (const std::optional<std::string> error = table_format_error(settings.formats))
        errors.push_back(*error);
    if (const std::optional<std::string> error = rope_option_error(vm))
        errors.push_back(*error);
    return settings;
}

// prepare_study's errors, one a line, after the command line's. A malformed budget was reported
// already; "give a budget" would repeat it.
void add_study_errors(const std::string& text, std::vector<std::string>& errors) {
    const bool budget_reported = std::any_of(errors.begin(), errors.end(), [](const std::string& earlier) {
        return earlier.find("iterations = ") != std::string::npos ||
               earlier.find("evaluations = ") != std::string::npos ||
               earlier.find("budget") != std::string::npos;
    });
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!(budget_reported && line.rfind("budget: give", 0) == 0))
            errors.push_back(line);
}

// The study the command line describes (a preset or study file, then the options), prepared; none
// when `errors` says why. `name` is the preset's, or "study". A plug-in module that cannot be
// used throws PluginError: failed work (exit 1) in one line, like an unreadable data file.
std::optional<PreparedStudy> prepare_command_study(const po::variables_map& vm, std::string& name,
                                                   std::vector<std::string>& errors) {
    Study study;
    const bool base_read = load_base_study(vm, study, name, errors);
    apply_study_options(vm, study, errors);
    // A preset or study file that could not be read would only add "no algorithm given" noise.
    if (!base_read)
        return std::nullopt;
    // The plug-ins first: the specs may name their components.
    const Components components = compose_components(study.plugins);
    try {
        return prepare_study(study, components.algorithms, components.problems);
    } catch (const std::invalid_argument& e) {
        add_study_errors(e.what(), errors);
    }
    return std::nullopt;
}

// Under mpirun, each rank read its own copy of the data: all must have read the same content.
// False, said by rank 0 alone, when they did not.
bool ranks_read_the_same(const PreparedStudy& prepared) {
    const auto differences = distributed_data_differences(prepared);
    if (differences.empty())
        return true;
    if (distributed_rank() == 0) {
        for (const auto& line : differences)
            std::cerr << "mhbench run: " << line << '\n';
        std::cerr << "mhbench run: every rank must read the same data files, plug-ins and programs; nothing "
                     "was run\n";
    }
    return false;
}

// A rank other than 0 under mpirun: it runs what rank 0 hands it, and touches no directory
// (runner/distribution/distributed.hpp).
int run_as_other_rank(const PreparedStudy& prepared, int threads) {
    const StopSignals signals;
    RunnerOptions worker;
    worker.threads = threads;
    worker.stop = &stop_requested;
    if (!prepared.study.by_precision)
        return run_study_anywhere(prepared, nullptr, worker).interrupted ? exit_interrupted : exit_ok;
    // Runs by precision: a round at a time, for as long as rank 0 (which sees the results) says.
    while (distributed_another_round(false))
        if (run_study_anywhere(prepared, nullptr, worker).interrupted)
            return exit_interrupted;
    return exit_ok;
}

// A shard's directory says which shard it holds ("shard = i/n\n", empty for the whole study), so
// that an unfinished one is resumed only as the same shard, and `mhbench merge` can check the
// set. False, said, when the stored runs of `dir` are of another share.
bool directory_holds_share(const std::filesystem::path& dir, const std::string& shard_line, bool overwrite) {
    const std::filesystem::path shard_file = dir / StudyFiles::shard;
    if (overwrite || !std::filesystem::exists(dir / StudyFiles::store))
        return true;
    const std::string previous = std::filesystem::exists(shard_file) ? read_whole_file(shard_file) : "";
    if (previous == shard_line)
        return true;
    const auto what = [](const std::string& line) {
        return line.empty() ? std::string("the whole study") : "shard " + line.substr(8, line.size() - 9);
    };
    std::cerr << "mhbench run: " << dir.string() << ": holds the runs of " << what(previous) << ", not of "
              << what(shard_line) << "; choose another --out or pass --overwrite\n";
    return false;
}

// context.ini of this session. The sessions that wrote the stored runs stay on record, unless
// those runs are discarded.
std::string session_context(const PreparedStudy& prepared, const RunSettings& settings, int threads,
                            const std::vector<std::string>& args, const std::filesystem::path& dir,
                            bool overwrite) {
    std::vector<std::string> command_line{"mhbench", "run"};
    command_line.insert(command_line.end(), args.begin(), args.end());
    std::string context =
        context_ini(threads, command_line) + distributed_context() + context_data_files(prepared.problems);
    if (settings.shard)
        context += "shard = " + shard_text(*settings.shard) + '\n';
    const bool resumed = !overwrite && std::filesystem::exists(dir / StudyFiles::store) &&
                         std::filesystem::exists(dir / StudyFiles::context);
    return context_with_history(context,
                                resumed ? context_sessions(read_whole_file(dir / StudyFiles::context)) : "");
}

// What a problem knows to be doubtful about itself (an optimum on a face of the box) is said
// before the runs, once per problem.
void print_problem_warnings(const PreparedStudy& prepared) {
    for (const PreparedProblem& problem : prepared.problems)
        for (const std::string& warning : problem.problem->warnings())
            std::cerr << "mhbench run: warning: " << problem.spec << ": " << warning << '\n';
}

struct TimedOutcome {
    RunnerOutcome outcome;
    double wall_seconds = 0;
};

// What the progress counts: the runs to do (the study's or the shard's), each weighted by the
// estimated cost the shards are balanced by (runner/distribution/shards.hpp), those the store holds
// already done (it may hold runs of other studies, kept for a larger one: only this study's count).
ProgressWork progress_work(const PreparedStudy& prepared, const StudyWriter& writer,
                           const std::optional<std::vector<std::int64_t>>& shard_runs) {
    std::vector<std::int64_t> runs;
    if (shard_runs) {
        runs = *shard_runs;
    } else {
        runs.resize(static_cast<std::size_t>(prepared.run_count()));
        for (std::size_t id = 0; id < runs.size(); ++id)
            runs[id] = static_cast<std::int64_t>(id);
    }
    return ProgressWork(estimated_run_costs(prepared), runs, writer.completed());
}

// The runs (this process's share under mpirun), with the progress display. A terminal gets the
// bar (after a second, so short studies print nothing); a batch log gets a plain line every
// --progress-interval seconds; --quiet gets neither. `after_runs_seconds`: the report's estimate,
// which the ETA includes (0 without one).
ProgressOptions progress_options(const po::variables_map& vm) {
    const bool forced = vm["progress"].as<bool>();
    ProgressOptions shown;
    shown.terminal = forced || stderr_is_terminal();
    shown.delay_seconds = forced ? 0.0 : 1.0;
    shown.line_interval = vm["progress-interval"].as<double>();
    return shown;
}

TimedOutcome run_with_progress(const PreparedStudy& prepared, StudyWriter& writer,
                               const po::variables_map& vm, int threads,
                               const std::optional<std::vector<std::int64_t>>& shard_runs, bool quiet,
                               double after_runs_seconds) {
    const ProgressOptions shown = progress_options(vm);
    // Costs only for a display: estimating them may run a few short calibration runs.
    ProgressBar progress(std::cerr,
                         quiet ? ProgressWork::uniform(0, 0) : progress_work(prepared, writer, shard_runs),
                         shown, after_runs_seconds);
    RunnerOptions runner;
    runner.threads = threads;
    runner.stop = &stop_requested;
    runner.run_ids = shard_runs;
    if (!quiet)
        runner.on_run_finished = [&progress](std::int64_t, std::int64_t, const RunRecord& record) {
            progress.update(record.run_id, record.evaluations);
        };

    const auto started = std::chrono::steady_clock::now();
    TimedOutcome timed;
    timed.outcome = run_study_anywhere(prepared, &writer, runner);
    progress.finish();
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;
    timed.wall_seconds = wall.count();
    return timed;
}

// Runs by precision: a line and a progress display per round (the runs a round adds are known
// only when it starts). The ETA is the round's: how many rounds follow depends on their results.
TimedOutcome run_rounds_with_progress(const PreparedStudy& prepared, StudyWriter& writer,
                                      const po::variables_map& vm, int threads, bool quiet) {
    const ProgressOptions shown = progress_options(vm);
    const std::vector<double> costs = quiet ? std::vector<double>{} : estimated_run_costs(prepared);
    std::unique_ptr<ProgressBar> progress;
    RunnerOptions runner;
    runner.threads = threads;
    runner.stop = &stop_requested;
    if (!quiet)
        runner.on_run_finished = [&progress](std::int64_t, std::int64_t, const RunRecord& record) {
            progress->update(record.run_id, record.evaluations);
        };
    PrecisionRoundHooks hooks;
    hooks.run = [&](const RunnerOptions& round) { return run_study_anywhere(prepared, &writer, round); };
    hooks.announce = [](bool more) { (void)distributed_another_round(more); };
    hooks.on_round = [&](const PrecisionRoundStart& round) {
        if (quiet)
            return;
        if (progress)
            progress->finish();
        std::cerr << "round " << round.round << ": " << count_of(round.runs.size(), "run") << " for "
                  << count_of(static_cast<std::size_t>(round.unsettled_cells), "cell")
                  << " short of the precision\n";
        progress = std::make_unique<ProgressBar>(std::cerr, ProgressWork(costs, round.runs, {}), shown);
    };
    const auto started = std::chrono::steady_clock::now();
    TimedOutcome timed;
    timed.outcome = run_study_by_precision(prepared, writer, runner, hooks);
    if (progress)
        progress->finish();
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;
    timed.wall_seconds = wall.count();
    return timed;
}

// The report, built from the directory alone, exactly as `mhbench report DIR` would.
int build_study_report(const std::filesystem::path& dir, const po::variables_map& vm,
                       const RunSettings& settings, bool quiet) {
    ReportOptions report;
    report.formats = settings.formats;
    report.figures = !vm["no-figures"].as<bool>();
    report.console_tables = vm["tables"].as<bool>();
    set_rope_options(vm, report);
    report.plot_script = companion_file("scripts/plot_study.py");
    report.stop = &stop_requested; // a Ctrl-C during the tables starts no figure
    std::ostringstream discarded;
    if (!quiet)
        std::cout << '\n';
    // Ctrl-C during the figures: one line on stderr from build_report; the same command completes.
    if (build_report(load_study(dir), report, quiet ? discarded : std::cout).interrupted)
        return exit_interrupted;
    return exit_ok;
}

// Rank 0 (or the one process): the study into `dir`, then its summary and report.
int run_into_directory(const PreparedStudy& prepared, const RunSettings& settings, int threads,
                       const std::filesystem::path& dir, const po::variables_map& vm,
                       const std::vector<std::string>& args) {
    // One writer per directory: taken before the directory is read, so that what is checked
    // below is what this process then writes to.
    std::optional<StudyLock> lock;
    try {
        lock.emplace(dir, "mhbench run");
    } catch (const StudyInUse& e) {
        std::cerr << "mhbench run: " << e.what() << "; wait for it or use another --out\n";
        return exit_failure;
    }
    const bool overwrite = vm["overwrite"].as<bool>();
    const std::optional<ShardSpec>& shard = settings.shard;
    const std::string shard_line = shard ? "shard = " + shard_text(*shard) + "\n" : "";
    if (!directory_holds_share(dir, shard_line, overwrite))
        return exit_failure;
    std::optional<std::vector<std::int64_t>> shard_runs;
    if (shard)
        shard_runs = shard_run_ids(prepared, shard->count)[static_cast<std::size_t>(shard->index - 1)];
    // From here on Ctrl-C means "stop after the runs under way"; before, it just ends the process.
    const StopSignals signals;
    const std::string context = session_context(prepared, settings, threads, args, dir, overwrite);
    StudyRunKeys keys = study_run_keys(prepared);
    keys.recompute_changed = vm["recompute-changed"].as<bool>();
    keys.run_ids = shard_runs; // a shard's directory holds its runs only
    StudyWriter writer(dir, study_ini(prepared.study), context, prepared.parameter_columns, overwrite,
                       prepared.algorithm_infos(), std::move(keys));
    for (const std::string& warning : writer.warnings())
        std::cerr << "mhbench run: warning: " << warning << '\n';
    if (const std::int64_t retried = writer.retried_failures(); retried > 0)
        std::cerr << "mhbench run: " << retried << (retried == 1 ? " run" : " runs")
                  << " of the store failed before; computing " << (retried == 1 ? "it" : "them")
                  << " again\n";
    if (shard)
        write_file_atomically(dir / StudyFiles::shard, shard_line);
    else
        std::filesystem::remove(dir / StudyFiles::shard);

    const bool quiet = vm["quiet"].as<bool>();
    if (!quiet)
        print_problem_warnings(prepared);
    // The ETA includes the report the runs end with (a shard's comes after the merge).
    const bool report = !shard && !vm["no-report"].as<bool>();
    const double report_seconds =
        report && !quiet ? estimate_report(prepared, !vm["no-figures"].as<bool>()).seconds() : 0.0;
    const TimedOutcome timed =
        prepared.study.by_precision
            ? run_rounds_with_progress(prepared, writer, vm, threads, quiet)
            : run_with_progress(prepared, writer, vm, threads, shard_runs, quiet, report_seconds);
    const RunnerOutcome& outcome = timed.outcome;
    if (outcome.interrupted) {
        std::cerr << "interrupted: " << outcome.kept << " of " << outcome.total << " runs kept in "
                  << dir.string() << "; run the same command again to resume\n";
        return exit_interrupted;
    }
    const auto [failed, total] = report_outcome(writer.summary(), dir, outcome, timed.wall_seconds, quiet);
    if (failed == total && total > 0) // nothing to report on, and nothing a script should take for a result
        return exit_failure;
    if (shard) { // a shard is part of a study: its report comes after the merge
        if (!quiet)
            std::cout << "shard " << shard_text(*shard) << " done; when all " << shard->count
                      << " are, join them with: mhbench merge OUT DIR...\n";
        return exit_ok;
    }
    if (vm["no-report"].as<bool>())
        return exit_ok;
    return build_study_report(dir, vm, settings, quiet);
}

} // namespace

int run_run_command(const std::vector<std::string>& args) {
    const po::options_description options = make_run_options();
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { print_run_help(options); }))
        return exit_ok;

    std::vector<std::string> errors;
    const RunSettings settings = check_run_settings(vm, errors);
    std::string name;
    std::optional<PreparedStudy> prepared;
    try {
        prepared = prepare_command_study(vm, name, errors);
    } catch (const PluginError& e) {
        std::cerr << "mhbench run: " << e.what() << '\n';
        return exit_failure;
    }
    if (!errors.empty()) {
        for (const auto& e : errors)
            std::cerr << "mhbench run: " << e << '\n';
        return exit_usage;
    }

    if (prepared->study.by_precision && settings.shard) {
        std::cerr
            << "mhbench run: runs = auto decides each round from the results of the last, which a shard "
               "cannot see; give a fixed --runs to shard the study (or run it under mpirun)\n";
        return exit_usage;
    }
    const int threads = resolve_thread_count(settings.threads);
    const std::filesystem::path dir = vm.count("out") != 0 ? vm["out"].as<std::string>() : "studies/" + name;
    if (vm["dry-run"].as<bool>()) {
        std::cout << dry_run_text(*prepared, dir, threads, !vm["no-report"].as<bool>(),
                                  !vm["no-figures"].as<bool>());
        return exit_ok;
    }
    if (!ranks_read_the_same(*prepared))
        return exit_failure;
    // Under mpirun, rank 0 alone touches the directory, prints and reports.
    if (distributed_rank() != 0)
        return run_as_other_rank(*prepared, threads);
    return run_into_directory(*prepared, settings, threads, dir, vm, args);
}

} // namespace mhb::cli
