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

#include "problems/parameters.hpp"
#include "problems/spec.hpp"
#include "results/report.hpp"
#include "results/store.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"
#include "runner/context.hpp"
#include "runner/parallel_runner.hpp"
#include "runner/progress.hpp"
#include "runner/study.hpp"
#include "runner/study_file.hpp"
#include "runner/study_presets.hpp"

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
// journal is safe either way: a half-written block is dropped on resume).
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
        std::snprintf(line, sizeof line, "    %-8s %s\n", p.name.c_str(), p.summary.c_str());
        out += line;
    }
    return out;
}

po::options_description make_options() {
    po::options_description d("Options");
    // clang-format off
    d.add_options()
        ("help,h", "this text")
        ("algorithms", po::value<std::vector<std::string>>()->multitoken()->composing(),
         "optimisers to compare, as name:key=value,...; several separated by spaces, or the option "
         "repeated (see `mhbench list algorithms`)")
        ("algorithm", po::value<std::vector<std::string>>()->multitoken()->composing(), "same as --algorithms")
        ("problems", po::value<std::vector<std::string>>()->multitoken()->composing(),
         "problems, as name:key=value,...; integer parameters may be ranges, e.g. f=1-24 "
         "(see `mhbench list problems`)")
        ("problem", po::value<std::vector<std::string>>()->multitoken()->composing(), "same as --problems")
        ("runs", po::value<std::string>(), "runs of each algorithm on each problem (default 20)")
        ("seed", po::value<std::string>(), "study seed, 0 to 2^64-1; every run's seed is derived from it (default 1)")
        ("iterations", po::value<std::string>(),
         "budget: iterations per run after the initialisation (iteration 0). A study needs "
         "--iterations or --evaluations; a preset brings its own")
        ("evaluations", po::value<std::string>(),
         "budget: function evaluations per run (1e5 is accepted); with --iterations, whichever is spent "
         "first ends the run. "
         "Either replaces both of a preset's budget values")
        ("target", po::value<double>(), "also stop a run once best f - f* <= this (problems with a known optimum)")
        ("threads", po::value<int>(), "worker threads (default: all hardware threads); results do not depend on it")
        ("out", po::value<std::string>(), "study directory (default: studies/<preset name, or 'study'>)")
        ("overwrite", po::bool_switch(), "replace a finished study (or another study's unfinished one) in --out")
        ("study", po::value<std::string>(), "start from a preset (see below); other options override its values")
        ("study-file", po::value<std::string>(),
         "start from a study file, e.g. DIR/study.ini of an earlier study; other options override its values")
        ("progress", po::bool_switch(), "show the progress bar even when stderr is not a terminal")
        ("no-report", po::bool_switch(), "do not build the report (tables, curve data, figures) after the study; "
                                         "`mhbench report DIR` builds it at any time")
        ("no-figures", po::bool_switch(), "build the report without figures (they take most of its time)")
        ("quiet,q", po::bool_switch(), "print nothing but errors (no progress bar, no summary, no tables)");
    // clang-format on
    return d;
}

void print_help(const po::options_description& options) {
    std::cout << "Usage: mhbench run [options]\n\n"
                 "Runs every algorithm on every problem, --runs times each, into a study directory\n"
                 "(study.ini, context.ini, runs.csv, curves.csv, checkpoints.csv, trajectories.csv,\n"
                 "timings.csv). The whole study is checked first and every error reported at once.\n"
                 "Results are identical for any --threads. Ctrl-C keeps the finished runs; running\n"
                 "the same command again resumes the study.\n\n"
              << options << "\nStudy presets (--study NAME):\n"
              << preset_lines()
              << "\nExamples:\n"
                 "  mhbench run --study paper\n"
                 "  mhbench run --study paper --evaluations 37500 --out studies/paper-equal-evals\n"
                 "  mhbench run --algorithms \"itlbo tlbo:np=30\" --algorithms pso:w=0.7 \\\n"
                 "              --problems sphere:dim=10 --iterations 200 --runs 30 --out studies/sphere\n"
                 "  mhbench run --study-file studies/sphere/study.ini --threads 1 --out /tmp/again\n";
}

std::vector<std::string> spec_list(const po::variables_map& vm, const char* plural, const char* singular) {
    std::vector<std::string> specs;
    for (const char* key : {plural, singular})
        if (vm.count(key) != 0)
            for (const auto& text : vm[key].as<std::vector<std::string>>())
                for (auto& spec : split_spec_list(text))
                    specs.push_back(std::move(spec));
    return specs;
}

// The study to start from: a preset, a study file, or an empty study. False if it could not be read.
bool load_base_study(const po::variables_map& vm, Study& study, std::string& name,
                     std::vector<std::string>& errors) {
    name = "study";
    try {
        if (vm.count("study") != 0 && vm.count("study-file") != 0) {
            errors.emplace_back("give --study or --study-file, not both");
            return false;
        }
        if (vm.count("study") != 0) {
            const StudyPreset& preset = find_study_preset(vm["study"].as<std::string>());
            study = preset.study;
            name = preset.name;
        } else if (vm.count("study-file") != 0) {
            study = read_study_file(vm["study-file"].as<std::string>());
        }
    } catch (const std::exception& e) {
        errors.emplace_back(e.what()); // reported with the option errors below
        return false;
    }
    return true;
}

// The options given on the command line, on top of the base study.
void apply_options(const po::variables_map& vm, Study& study, std::vector<std::string>& errors) {
    if (auto a = spec_list(vm, "algorithms", "algorithm"); !a.empty())
        study.algorithms = std::move(a);
    if (auto p = spec_list(vm, "problems", "problem"); !p.empty())
        study.problems = std::move(p);
    // Integers may be written 1e5, as in specs; range checks come with the study's validation.
    const auto integer_option = [&](const char* key) -> std::optional<std::int64_t> {
        if (vm.count(key) == 0)
            return std::nullopt;
        const auto& text = vm[key].as<std::string>();
        long long value = 0;
        if (!parse_integer(text, value)) {
            errors.push_back(std::string(key) + " = " + text + " is not an integer");
            return std::nullopt;
        }
        return value;
    };
    if (const auto runs = integer_option("runs"))
        study.runs = *runs;
    if (vm.count("seed") != 0) {
        const auto& text = vm["seed"].as<std::string>();
        std::istringstream in(text);
        std::uint64_t seed = 0;
        if (text.empty() || text[0] == '-' || !(in >> seed) || !in.eof())
            errors.push_back("seed = " + text + " is not an integer in [0, 2^64)");
        study.seed = seed;
    }
    if (vm.count("iterations") != 0 || vm.count("evaluations") != 0) {
        study.budget.max_iterations.reset();
        study.budget.max_evaluations.reset();
        study.budget.max_iterations = integer_option("iterations");
        study.budget.max_evaluations = integer_option("evaluations");
    }
    if (vm.count("target") != 0)
        study.budget.target_error = vm["target"].as<double>();
}

void print_summary(const std::filesystem::path& dir, const RunnerOutcome& outcome, double wall_seconds) {
    const StudyData data = load_study(dir);
    std::int64_t failed = 0;
    std::int64_t evaluations = 0;
    for (const auto& r : data.runs) {
        failed += r.ok ? 0 : 1;
        evaluations += r.evaluations;
    }
    char line[256];
    std::snprintf(line, sizeof line, "%zu runs (%lld failed), %lld evaluations, %.3g s wall",
                  data.runs.size(), static_cast<long long>(failed), static_cast<long long>(evaluations),
                  wall_seconds);
    std::cout << "study finished: " << line;
    if (outcome.resumed > 0)
        std::cout << " (" << outcome.resumed << " runs resumed from an earlier session)";
    std::cout << "\nresults in " << dir.string() << '\n';
    if (failed > 0)
        std::cout << "failed runs carry their message in runs.csv (column 'message')\n";
}

} // namespace

int run_run_command(const std::vector<std::string>& args) {
    const po::options_description options = make_options();
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { print_help(options); }))
        return exit_ok;

    std::vector<std::string> errors;
    int threads = 0;
    if (vm.count("threads") != 0) {
        threads = vm["threads"].as<int>();
        if (threads < 1)
            errors.push_back("threads = " + std::to_string(threads) + " is outside [1, inf)");
    }
    Study study;
    std::string name;
    const bool base_read = load_base_study(vm, study, name, errors);
    apply_options(vm, study, errors);
    std::optional<PreparedStudy> prepared;
    // A preset or study file that could not be read would only add "no algorithm given" noise.
    if (base_read) {
        try {
            prepared = prepare_study(study);
        } catch (const std::invalid_argument& e) {
            std::istringstream in(e.what());
            for (std::string line; std::getline(in, line);) {
                // A malformed --iterations/--evaluations was reported already; "no budget" would repeat it.
                const bool budget_echo =
                    line.rfind("budget: give", 0) == 0 &&
                    std::any_of(errors.begin(), errors.end(), [](const std::string& earlier) {
                        return earlier.rfind("iterations = ", 0) == 0 ||
                               earlier.rfind("evaluations = ", 0) == 0;
                    });
                if (!budget_echo)
                    errors.push_back(line);
            }
        }
    }
    if (!errors.empty()) {
        for (const auto& e : errors)
            std::cerr << "mhbench run: " << e << '\n';
        return exit_usage;
    }

    threads = resolve_thread_count(threads);
    const std::filesystem::path dir = vm.count("out") != 0 ? vm["out"].as<std::string>() : "studies/" + name;
    std::vector<std::string> command_line{"mhbench", "run"};
    command_line.insert(command_line.end(), args.begin(), args.end());
    // From here on Ctrl-C means "stop after the runs under way"; before, it just ends the process.
    const StopSignals signals;
    StudyWriter writer(dir, study_ini(prepared->study), context_ini(threads, command_line),
                       prepared->parameter_columns, vm["overwrite"].as<bool>());

    const bool quiet = vm["quiet"].as<bool>();
    const bool forced = vm["progress"].as<bool>();
    const bool show_progress = !quiet && (forced || stderr_is_terminal());
    // Without --progress the bar waits a second, so that short studies print nothing.
    ProgressBar progress(std::cerr, prepared->run_count(),
                         static_cast<std::int64_t>(writer.completed().size()), forced ? 0.0 : 1.0);
    RunnerOptions runner;
    runner.threads = threads;
    runner.stop = &stop_requested;
    if (show_progress)
        runner.on_run_finished = [&progress](std::int64_t kept, std::int64_t) { progress.update(kept); };

    const auto started = std::chrono::steady_clock::now();
    const RunnerOutcome outcome = run_study(*prepared, writer, runner);
    progress.finish();
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;

    if (outcome.interrupted) {
        std::cerr << "interrupted: " << outcome.kept << " of " << outcome.total << " runs kept in "
                  << dir.string() << "; run the same command again to resume\n";
        return exit_interrupted;
    }
    if (!quiet)
        print_summary(dir, outcome, wall.count());
    if (vm["no-report"].as<bool>())
        return exit_ok;
    // The report is built from the directory alone, exactly as `mhbench report DIR` would.
    ReportOptions report;
    report.figures = !vm["no-figures"].as<bool>();
    report.plot_script = std::filesystem::path(MHB_SOURCE_DIR) / "scripts" / "plot_study.py";
    std::ostringstream discarded;
    if (!quiet)
        std::cout << '\n';
    build_report(load_study(dir), report, quiet ? discarded : std::cout);
    return exit_ok;
}

} // namespace mhb::cli
