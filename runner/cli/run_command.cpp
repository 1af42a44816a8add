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
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/core/spec.hpp"
#include "problems/core/text_excerpt.hpp"
#include "results/report/report.hpp"
#include "results/store/csv.hpp"
#include "results/store/store.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"
#include "runner/distribution/distributed.hpp"
#include "runner/distribution/shards.hpp"
#include "runner/execution/context.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/execution/progress.hpp"
#include "runner/execution/run_identity.hpp"
#include "runner/execution/study_lock.hpp"
#include "runner/plugins/components.hpp"
#include "runner/study/dry_run.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "runner/study/study_options.hpp"
#include "runner/study/study_presets.hpp"

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

std::string preset_lines() {
    std::string out;
    for (const auto& p : study_presets()) {
        char line[256];
        std::snprintf(line, sizeof line, "    %-13s %s\n", p.name.c_str(), p.summary.c_str());
        out += line;
    }
    return out;
}

po::options_description make_options() {
    po::options_description run("Running");
    // clang-format off
    run.add_options()
        ("help,h", "this text")
        ("study", po::value<std::string>(), "start from a preset (see below); other options override its values")
        ("study-file", po::value<std::string>(),
         "start from a study file (scripts/studies/*.ini are examples, DIR/study.ini of an earlier study "
         "another); other options override its values")
        ("dry-run", po::bool_switch(),
         "print the expanded study (algorithms with their labels, problems, budgets, runs, evaluations and a "
         "time estimate from a short calibration) and run nothing")
        ("shard", po::value<std::string>(),
         "i/n: run only shard i of n of the study (a deterministic share, balanced by estimated cost) into "
         "--out; `mhbench merge OUT DIR...` joins the n shard directories into the study one process writes "
         "(see scripts/slurm-array.sh)")
        ("threads", po::value<std::string>(), "worker threads (default: all hardware threads); results do not depend on it")
        ("out", po::value<std::string>(), "study directory (default: studies/<preset name, or 'study'>)")
        ("overwrite", po::bool_switch(),
         "empty the study store in --out and do every run again (needed when a data file, labelled "
         "algorithm or seed changed under stored runs)")
        ("recompute-changed", po::bool_switch(),
         "compute again the stored runs that something changed under (an algorithm's or problem's "
         "implementation version, a data file, a labelled algorithm, the seed) and keep every other "
         "stored run; without it such a study is refused")
        ("progress", po::bool_switch(), "draw the progress bar even when stderr is not a terminal")
        ("progress-interval", po::value<double>()->default_value(10.0, "10"),
         "seconds between the plain progress lines written when stderr is not a terminal (batch logs)")
        ("no-report", po::bool_switch(), "do not build the report (tables, curve data, figures) after the study; "
                                         "`mhbench report DIR` builds it at any time")
        ("no-figures", po::bool_switch(), "build the report without figures (they take most of its time)")
        ("quiet,q", po::bool_switch(), "print nothing but errors (no progress bar, no summary, no tables)");
    // clang-format on
    po::options_description all;
    all.add(study_options()).add(run);
    return all;
}

void print_help(const po::options_description& options) {
    std::cout
        << "Usage: mhbench run [options]\n\n"
           "Runs every algorithm on every problem under every budget, --runs times each, into a\n"
           "study directory (study.ini, context.ini, algorithms.csv, runs.csv, curves.csv, ...).\n"
           "The whole study, command line and study file together, is checked first and every\n"
           "error reported at once. By default every algorithm starts run r on a problem from the\n"
           "same random stream (common random numbers), so runs pair across algorithms and the\n"
           "report uses paired tests. Results are identical for any --threads. Every finished run is\n"
           "kept in DIR/store.bin: after Ctrl-C or a kill the same command resumes, and a larger\n"
           "study into the same --out (more runs, algorithms, problems, budgets) computes only the\n"
           "runs it lacks. Under `mpirun -np N` (an MPI build) the runs spread over the ranks.\n"
           "One process writes a directory at a time: while DIR/.mhbench.lock is held, another\n"
           "run, merge or report into DIR is refused with the holder's pid and host.\n\n"
        << options << "\nStudy presets (--study NAME; the files are in scripts/studies/):\n"
        << preset_lines()
        << "\nExamples:\n"
           "  mhbench run --study paper\n"
           "  mhbench run --study ablation --dry-run\n"
           "  mhbench run --study cec2017-smoke      # the CEC 2017 protocol, small\n"
           "  mhbench run --study cec2017 --problems \"cec2017:f={1,3-30},dim={10,30}\"\n"
           "  mhbench run --study paper --evaluations 37500 --out studies/paper-equal-evals\n"
           "  mhbench run --algorithms \"itlbo:tutorial={on,off},obl={on,off} tlbo\" \\\n"
           "              --problems sphere:dim=10 --budget iterations=200 --budget evaluations=2e4 \\\n"
           "              --runs 30 --out studies/sphere\n"
           "  mhbench run --study-file studies/sphere/study.ini --threads 1 --out /tmp/again\n";
}

// The study to start from: a preset, a study file, or an empty study. False if none could be read.
bool load_base_study(const po::variables_map& vm, Study& study, std::string& name,
                     std::vector<std::string>& errors) {
    name = "study";
    if (vm.count("study") != 0 && vm.count("study-file") != 0) {
        errors.emplace_back("give --study or --study-file, not both");
        return false;
    }
    if (vm.count("study") != 0) {
        try {
            const StudyPreset& preset = find_study_preset(vm["study"].as<std::string>());
            study = preset.study;
            name = preset.name;
        } catch (const std::exception& e) {
            errors.emplace_back(e.what());
            return false;
        }
    } else if (vm.count("study-file") != 0) {
        const std::filesystem::path path = vm["study-file"].as<std::string>();
        std::string text;
        try {
            text = read_study_text(path);
        } catch (const std::exception& e) {
            errors.emplace_back(e.what());
            return false;
        }
        // Every error of the file is kept, with its line, and reported with the command line's.
        parse_study_file(text, path.string(), study, errors);
    }
    return true;
}

// The study options given on the command line, on top of the base study.
void apply_options(const po::variables_map& vm, Study& study, std::vector<std::string>& errors) {
    StudyOptionReader reader(study);
    const po::options_description declared = study_options();
    for (const auto& option : declared.options()) {
        const std::string& key = option->long_name();
        if (vm.count(key) == 0)
            continue;
        if (const auto* many = boost::any_cast<std::vector<std::string>>(&vm[key].value()))
            for (const auto& value : *many)
                reader.apply(key, value, "", errors);
        else
            reader.apply(key, vm[key].as<std::string>(), "", errors);
    }
    reader.finish(errors);
}

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
                  << (dir / StudyFiles::runs).string() << " (column 'message'). The first:\n";
        for (const auto& r : summary.first_failures) {
            std::string message = r.message; // one line each, as runs.csv shows it
            std::replace(message.begin(), message.end(), '\n', ' ');
            std::cerr << "  run " << r.run_id << " (" << r.algorithm << " on " << r.problem << ", run "
                      << r.run_index << "): " << message << '\n';
        }
    }
    return {failed, total};
}

} // namespace

int run_run_command(const std::vector<std::string>& args) {
    const po::options_description options = make_options();
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { print_help(options); }))
        return exit_ok;

    std::vector<std::string> errors;
    int threads = 0;
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
            threads = static_cast<int>(std::min<long long>(value, 100000));
    }
    std::optional<ShardSpec> shard;
    if (vm.count("shard") != 0) {
        try {
            shard = parse_shard(vm["shard"].as<std::string>());
        } catch (const std::invalid_argument& e) {
            errors.emplace_back(e.what());
        }
    }
    Study study;
    std::string name;
    const bool base_read = load_base_study(vm, study, name, errors);
    apply_options(vm, study, errors);
    std::optional<PreparedStudy> prepared;
    // A preset or study file that could not be read would only add "no algorithm given" noise.
    if (base_read) {
        // The plug-ins first: the specs may name their components. A module that cannot be used
        // is failed work (exit 1) in one line, like an unreadable data file, and ends here.
        std::optional<Components> components;
        try {
            components.emplace(compose_components(study.plugins));
        } catch (const PluginError& e) {
            std::cerr << "mhbench run: " << e.what() << '\n';
            return exit_failure;
        }
        try {
            prepared = prepare_study(study, components->algorithms, components->problems);
        } catch (const std::invalid_argument& e) {
            // A malformed budget was reported already; "give a budget" would repeat it.
            const bool budget_reported =
                std::any_of(errors.begin(), errors.end(), [](const std::string& earlier) {
                    return earlier.find("iterations = ") != std::string::npos ||
                           earlier.find("evaluations = ") != std::string::npos ||
                           earlier.find("budget") != std::string::npos;
                });
            std::istringstream in(e.what());
            for (std::string line; std::getline(in, line);)
                if (!(budget_reported && line.rfind("budget: give", 0) == 0))
                    errors.push_back(line);
        }
    }
    if (!errors.empty()) {
        for (const auto& e : errors)
            std::cerr << "mhbench run: " << e << '\n';
        return exit_usage;
    }

    threads = resolve_thread_count(threads);
    const std::filesystem::path dir = vm.count("out") != 0 ? vm["out"].as<std::string>() : "studies/" + name;
    if (vm["dry-run"].as<bool>()) {
        std::cout << dry_run_text(*prepared, dir, threads);
        return exit_ok;
    }
    // Under mpirun, each rank read its own copy of the data: all must have read the same content.
    if (const auto differences = distributed_data_differences(*prepared); !differences.empty()) {
        if (distributed_rank() == 0) {
            for (const auto& line : differences)
                std::cerr << "mhbench run: " << line << '\n';
            std::cerr
                << "mhbench run: every rank must read the same data files, plug-ins and programs; nothing "
                   "was run\n";
        }
        return exit_failure;
    }
    // Under mpirun, rank 0 alone touches the directory, prints and reports; the other ranks run
    // what it hands them (runner/distribution/distributed.hpp).
    if (distributed_rank() != 0) {
        const StopSignals signals;
        RunnerOptions worker;
        worker.threads = threads;
        worker.stop = &stop_requested;
        return run_study_anywhere(*prepared, nullptr, worker).interrupted ? exit_interrupted : exit_ok;
    }
    // One writer per directory: taken before the directory is read, so that what is checked
    // below is what this process then writes to.
    std::optional<StudyLock> lock;
    try {
        lock.emplace(dir, "mhbench run");
    } catch (const StudyInUse& e) {
        std::cerr << "mhbench run: " << e.what() << "; wait for it or use another --out\n";
        return exit_failure;
    }
    std::vector<std::string> command_line{"mhbench", "run"};
    command_line.insert(command_line.end(), args.begin(), args.end());
    // A shard's directory says which shard it holds, so that an unfinished one is resumed only as
    // the same shard, and `mhbench merge` can check the set.
    const std::string shard_line = shard ? "shard = " + shard_text(*shard) + "\n" : "";
    const std::filesystem::path shard_file = dir / StudyFiles::shard;
    if (!vm["overwrite"].as<bool>() && std::filesystem::exists(dir / StudyFiles::store)) {
        const std::string previous = std::filesystem::exists(shard_file) ? read_whole_file(shard_file) : "";
        if (previous != shard_line) {
            const auto what = [](const std::string& line) {
                return line.empty() ? std::string("the whole study")
                                    : "shard " + line.substr(8, line.size() - 9);
            };
            std::cerr << "mhbench run: " << dir.string() << ": holds the runs of " << what(previous)
                      << ", not of " << what(shard_line) << "; choose another --out or pass --overwrite\n";
            return exit_failure;
        }
    }
    std::optional<std::vector<std::int64_t>> shard_runs;
    if (shard)
        shard_runs = shard_run_ids(*prepared, shard->count)[static_cast<std::size_t>(shard->index - 1)];
    // From here on Ctrl-C means "stop after the runs under way"; before, it just ends the process.
    const StopSignals signals;
    std::string context =
        context_ini(threads, command_line) + distributed_context() + context_data_files(prepared->problems);
    if (shard)
        context += "shard = " + shard_text(*shard) + '\n';
    // The sessions that wrote the stored runs stay on record, unless those runs are discarded.
    const bool resumed = !vm["overwrite"].as<bool>() && std::filesystem::exists(dir / StudyFiles::store) &&
                         std::filesystem::exists(dir / StudyFiles::context);
    context = context_with_history(
        context, resumed ? context_sessions(read_whole_file(dir / StudyFiles::context)) : "");
    StudyRunKeys keys = study_run_keys(*prepared);
    keys.recompute_changed = vm["recompute-changed"].as<bool>();
    keys.run_ids = shard_runs; // a shard's directory holds its runs only
    StudyWriter writer(dir, study_ini(prepared->study), context, prepared->parameter_columns,
                       vm["overwrite"].as<bool>(), prepared->algorithms, std::move(keys));
    for (const std::string& warning : writer.warnings())
        std::cerr << "mhbench run: warning: " << warning << '\n';
    if (shard)
        write_file_atomically(shard_file, shard_line);
    else
        std::filesystem::remove(shard_file);

    const bool quiet = vm["quiet"].as<bool>();
    // What a problem knows to be doubtful about itself (an optimum on a face of the box) is said
    // before the runs, once per problem.
    if (!quiet)
        for (std::size_t p = 0; p < prepared->problems.size(); ++p)
            for (const std::string& warning : prepared->problems[p]->warnings())
                std::cerr << "mhbench run: warning: " << prepared->problem_specs[p] << ": " << warning
                          << '\n';
    const bool forced = vm["progress"].as<bool>();
    // A terminal gets the bar (after a second, so short studies print nothing); a batch log gets a
    // plain line every --progress-interval seconds; --quiet gets neither.
    ProgressOptions shown;
    shown.terminal = forced || stderr_is_terminal();
    shown.delay_seconds = forced ? 0.0 : 1.0;
    shown.line_interval = vm["progress-interval"].as<double>();
    const std::int64_t to_do =
        shard_runs ? static_cast<std::int64_t>(shard_runs->size()) : prepared->run_count();
    // The store may hold runs of other studies (kept for a larger one): count this study's only.
    std::int64_t stored = static_cast<std::int64_t>(writer.completed().size());
    if (shard_runs)
        stored = std::count_if(shard_runs->begin(), shard_runs->end(),
                               [&](std::int64_t id) { return writer.completed().count(id) != 0; });
    ProgressBar progress(std::cerr, to_do, stored, shown);
    RunnerOptions runner;
    runner.threads = threads;
    runner.stop = &stop_requested;
    runner.run_ids = shard_runs;
    if (!quiet)
        runner.on_run_finished = [&progress](std::int64_t kept, std::int64_t, std::int64_t evaluations) {
            progress.update(kept, evaluations);
        };

    const auto started = std::chrono::steady_clock::now();
    const RunnerOutcome outcome = run_study_anywhere(*prepared, &writer, runner);
    progress.finish();
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;

    if (outcome.interrupted) {
        std::cerr << "interrupted: " << outcome.kept << " of " << outcome.total << " runs kept in "
                  << dir.string() << "; run the same command again to resume\n";
        return exit_interrupted;
    }
    const auto [failed, total] = report_outcome(writer.summary(), dir, outcome, wall.count(), quiet);
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
    // The report is built from the directory alone, exactly as `mhbench report DIR` would.
    ReportOptions report;
    report.figures = !vm["no-figures"].as<bool>();
    report.plot_script = std::filesystem::path(MHB_SOURCE_DIR) / "scripts" / "plot_study.py";
    report.stop = &stop_requested; // a Ctrl-C during the tables starts no figure
    std::ostringstream discarded;
    if (!quiet)
        std::cout << '\n';
    // Ctrl-C during the figures: one line on stderr from build_report; the same command completes.
    if (build_report(load_study(dir), report, quiet ? discarded : std::cout).interrupted)
        return exit_interrupted;
    return exit_ok;
}

} // namespace mhb::cli
