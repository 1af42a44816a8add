// Stopping a report while its figures are drawn (issue 10): SIGKILL leaves no plotting process
// behind, Ctrl-C ends with the interrupted outcome (exit 130) and one line, never a traceback, and
// the same `mhbench report` afterwards draws every figure. ReportSignals drives build_report in a
// forked process with a stand-in plotting script that sleeps (deterministic); the Slow tests run
// the real binary and the real scripts/plot_study.py, stopped in the middle of its figures.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "cli_harness.hpp"
#include "results/report/report.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"
#include "support/files.hpp"
#include "support/processes.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;
using mhb::test_support::read_text;

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = mhb::test_support::fresh_temporary_path("mhb_report_signals_", name);
    fs::create_directories(dir);
    return dir;
}

using mhb::test_support::processes_with;
using mhb::test_support::wait_until;

int exit_code_of(int status) {
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

// Files in `dir` whose name holds ".tmp" (a figure or table written half), and figures drawn.
std::vector<std::string> temporary_files(const fs::path& dir) {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(dir, ec))
        if (e.path().filename().string().find(".tmp") != std::string::npos)
            out.push_back(e.path().string());
    return out;
}

std::size_t count_with_extension(const fs::path& dir, const std::string& extension) {
    std::size_t n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        n += e.path().extension() == extension ? 1U : 0U;
    return n;
}

RunRecord pmsm_run(std::int64_t id, const std::string& algorithm, const std::string& problem,
                   std::int64_t index) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = algorithm;
    r.problem = problem;
    r.run_index = index;
    r.seed = 7;
    r.best_f = 4.0 + static_cast<double>(id % 5);
    r.f_opt = 3.9;
    r.evaluations = 100;
    r.iterations = 1;
    r.best_x = {0.33, 0.00324, 0.00324, 0.0776};
    r.parameter_names = {"Rs", "Ld", "Lq", "psi"};
    r.true_parameters = r.best_x;
    r.x_opt = r.best_x;
    r.curve = {{0, 50, r.best_f + 1.0, r.best_x}, {1, 100, r.best_f, r.best_x}};
    r.checkpoints = {{1, r.best_f + 2.0}, {100, r.best_f}};
    return r;
}

const std::vector<std::string> problems = {"pmsm:load=2,speed=2500", "pmsm:load=2,speed=1500"};

// Two PMSM problems x two algorithms x three runs: eleven figures, a few seconds.
StudyData study_in_memory(const fs::path& directory) {
    StudyData data;
    data.directory = directory;
    data.parameter_columns = {"Rs", "Ld", "Lq", "psi"};
    std::int64_t id = 0;
    for (const auto& problem : problems)
        for (const char* algorithm : {"itlbo", "pso"})
            for (std::int64_t i = 0; i < 3; ++i, ++id)
                data.runs.push_back(pmsm_run(id, algorithm, problem, i));
    return data;
}

// The same study written as a directory, for the CLI.
void write_study(const fs::path& dir) {
    StudyWriter writer(dir, "report signals test\n", "threads=1\n", {"Rs", "Ld", "Lq", "psi"}, false);
    for (const auto& r : study_in_memory(dir).runs)
        writer.append(r, 0.0);
    writer.finish();
}

// A stand-in for plot_study.py that only sleeps (and has no signal handler of its own): its path, a
// fresh folder with a space and a quote in its name, is the marker that finds it in /proc.
fs::path sleeping_script(const fs::path& dir) {
    const fs::path folder = dir / "stand-in plot's \"scripts\"";
    fs::create_directories(folder);
    const fs::path script = folder / "sleeping_plot.py";
    std::ofstream(script) << "import time\ntime.sleep(60)\n";
    return script;
}

// build_report in a forked process (the stand-in for mhbench), in a process group of its own as a
// shell's foreground job is; its error stream goes to `errors`. The process exits 130 when the
// report says interrupted, 0 otherwise, 1 on an exception.
pid_t report_in_child(const StudyData& study, ReportOptions options, const fs::path& errors) {
    const pid_t pid = ::fork();
    if (pid != 0) {
        if (pid > 0)
            ::setpgid(pid, pid);
        return pid;
    }
    ::setpgid(0, 0);
    int code = 1;
    try {
        std::ofstream error_stream(errors);
        options.errors = &error_stream;
        std::ostringstream console;
        code = build_report(study, options, console).interrupted ? 130 : 0;
    } catch (...) {
    }
    ::_exit(code);
}

bool matplotlib_available() {
    return find_matplotlib_python(ReportOptions().python_candidates).has_value();
}

TEST(ReportSignals, KillingTheReportKillsThePlottingScript) {
    if (!matplotlib_available())
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = fresh_dir("sigkill");
    ReportOptions options;
    options.out_dir = dir / "report";
    options.plot_script = sleeping_script(dir);
    const pid_t report = report_in_child(study_in_memory(dir / "study"), options, dir / "errors.txt");
    ASSERT_GT(report, 0);
    const std::vector<std::string> marker = {options.plot_script.string()};
    ASSERT_TRUE(wait_until([&] { return !processes_with(marker).empty(); }, 30.0))
        << "the plotting script never started";
    ::kill(report, SIGKILL);
    int status = 0;
    ::waitpid(report, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    EXPECT_TRUE(wait_until([&] { return processes_with(marker).empty(); }, 5.0))
        << "the plotting script outlived the report";
    EXPECT_TRUE(
        fs::exists(dir / "report" / "fitness_pmsm_load_2_speed_2500.md")); // written before the figures
    EXPECT_EQ(temporary_files(dir / "report"), std::vector<std::string>{});
}

TEST(ReportSignals, CtrlCEndsTheFiguresWithTheInterruptedOutcomeAndOneLine) {
    if (!matplotlib_available())
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = fresh_dir("sigint");
    ReportOptions options;
    options.out_dir = dir / "my report";
    options.plot_script = sleeping_script(dir);
    const StudyData study = study_in_memory(dir / "study");
    const pid_t report = report_in_child(study, options, dir / "errors.txt");
    ASSERT_GT(report, 0);
    const std::vector<std::string> marker = {options.plot_script.string()};
    ASSERT_TRUE(wait_until([&] { return !processes_with(marker).empty(); }, 30.0));
    const auto stopped = std::chrono::steady_clock::now();
    ::kill(-report, SIGINT); // Ctrl-C: the whole foreground group, report and script
    int status = 0;
    ::waitpid(report, &status, 0);
    // The stand-in ignores SIGINT (it starts so) and has no handler: the report's SIGTERM ended it.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - stopped).count(), 10.0);
    EXPECT_EQ(exit_code_of(status), 130);
    EXPECT_EQ(read_text(dir / "errors.txt"), "figures interrupted; run `mhbench report " +
                                                 study.directory.string() + " --out '" +
                                                 options.out_dir.string() + "'` to draw them\n");
    EXPECT_TRUE(processes_with(marker).empty());
    EXPECT_TRUE(fs::exists(options.out_dir / "report.md")); // every table is still written
    EXPECT_FALSE(fs::exists(options.out_dir / "figures" / "plot_study.log"));
}

TEST(ReportSignals, AStopAlreadyAskedForStartsNoFigure) {
    const fs::path dir = fresh_dir("stop_flag");
    ReportOptions options;
    options.out_dir = dir / "report";
    options.plot_script = sleeping_script(dir);
    const std::atomic<bool> stop{true};
    options.stop = &stop;
    std::ostringstream console;
    std::ostringstream errors;
    options.errors = &errors;
    EXPECT_TRUE(build_report(study_in_memory(dir / "study"), options, console).interrupted);
    EXPECT_EQ(errors.str(), "figures interrupted; run `mhbench report " + (dir / "study").string() +
                                " --out " + options.out_dir.string() + "` to draw them\n");
    EXPECT_TRUE(fs::exists(dir / "report" / "fitness_pmsm_load_2_speed_2500.md"));
    options.figures = false; // nothing was to be drawn: nothing was interrupted
    EXPECT_FALSE(build_report(study_in_memory(dir / "study"), options, console).interrupted);
}

// `mhbench ARGS` started in a process group of its own (a shell's foreground job), its output in
// `out` and `err`.
pid_t start_mhbench(const std::vector<std::string>& arguments, const fs::path& out, const fs::path& err) {
    std::vector<std::string> text = {MHB_CLI_PATH};
    text.insert(text.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (auto& t : text)
        argv.push_back(t.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::setpgid(0, 0);
        const int out_fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (out_fd < 0 || err_fd < 0 || ::dup2(out_fd, 1) < 0 || ::dup2(err_fd, 2) < 0)
            ::_exit(127);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    if (pid > 0)
        ::setpgid(pid, pid);
    return pid;
}

// The real script, drawing the figures of `study` (its report folder is in its command line).
std::vector<std::string> plot_script_of(const fs::path& study) {
    return {"plot_study.py", (study / "report").string()};
}

// Slow: matplotlib's start, then a second run that draws every figure (10 to 30 s in all).
TEST(SlowReportSignalsCli, SigkillDuringFiguresLeavesNoProcessAndTheSameCommandCompletes) {
    if (!matplotlib_available())
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = fresh_dir("cli_sigkill");
    const fs::path study = dir / "a study";
    write_study(study);
    const pid_t mhbench =
        start_mhbench({"report", study.string()}, dir / "first.stdout", dir / "first.stderr");
    ASSERT_GT(mhbench, 0);
    ASSERT_TRUE(wait_until([&] { return !processes_with(plot_script_of(study)).empty(); }, 60.0))
        << read_text(dir / "first.stderr");
    ::kill(mhbench, SIGKILL);
    int status = 0;
    ::waitpid(mhbench, &status, 0);
    EXPECT_TRUE(wait_until([&] { return processes_with(plot_script_of(study)).empty(); }, 5.0))
        << "plot_study.py outlived mhbench";

    const auto again = mhb::testing_cli::run_mhbench("report '" + study.string() + "'");
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.err, "");
    const fs::path figures = study / "report" / "figures";
    // One figure per kind with a panel per problem, the parameters and the CD diagram (issue 37).
    EXPECT_GE(count_with_extension(figures, ".png"), 7U);
    EXPECT_EQ(count_with_extension(figures, ".png"), count_with_extension(figures, ".pdf"));
    EXPECT_EQ(temporary_files(study / "report"), std::vector<std::string>{});
}

// Slow: the figures are interrupted once the first is drawn, then drawn again in full (10 to 40 s).
TEST(SlowReportSignalsCli, CtrlCDuringFiguresExitsInterruptedWithoutTraceback) {
    if (!matplotlib_available())
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = fresh_dir("cli_sigint");
    const fs::path study = dir / "a study";
    write_study(study);
    const fs::path figures = study / "report" / "figures";
    // A temporary figure of a run that was killed: the next run of the script removes it.
    fs::create_directories(figures);
    const pid_t gone = ::fork();
    if (gone == 0)
        ::_exit(0);
    ::waitpid(gone, nullptr, 0);
    const fs::path stale = figures / (".convergence_iteration_x.png.tmp-" + std::to_string(gone));
    std::ofstream(stale) << "half a PNG";

    const pid_t mhbench =
        start_mhbench({"report", study.string()}, dir / "first.stdout", dir / "first.stderr");
    ASSERT_GT(mhbench, 0);
    ASSERT_TRUE(wait_until([&] { return count_with_extension(figures, ".png") > 0; }, 60.0))
        << read_text(dir / "first.stderr");
    EXPECT_FALSE(fs::exists(stale));
    ::kill(-mhbench, SIGINT); // Ctrl-C in a terminal: mhbench and the script together
    int status = 0;
    ::waitpid(mhbench, &status, 0);
    const std::string err = read_text(dir / "first.stderr");
    EXPECT_EQ(exit_code_of(status), 130) << err;
    EXPECT_EQ(err, "figures interrupted; run `mhbench report '" + study.string() + "'` to draw them\n");
    EXPECT_EQ(err.find("Traceback"), std::string::npos);
    EXPECT_TRUE(wait_until([&] { return processes_with(plot_script_of(study)).empty(); }, 5.0));
    EXPECT_EQ(temporary_files(study / "report"), std::vector<std::string>{});
    EXPECT_FALSE(fs::exists(figures / "plot_study.log"));
    const std::size_t drawn_before = count_with_extension(figures, ".png");

    const auto again = mhb::testing_cli::run_mhbench("report '" + study.string() + "'");
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.err, "");
    EXPECT_NE(again.out.find("figures: " + figures.string()), std::string::npos) << again.out;
    EXPECT_GT(count_with_extension(figures, ".png"), drawn_before); // the interruption left some out
    EXPECT_EQ(count_with_extension(figures, ".png"), count_with_extension(figures, ".pdf"));
    EXPECT_EQ(temporary_files(study / "report"), std::vector<std::string>{});
}

} // namespace
} // namespace mhb
