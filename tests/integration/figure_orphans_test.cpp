// SIGKILL of `mhbench report` while its figure script runs, the script having started a program of
// its own (issue 36): neither the script nor what it started outlives mhbench. The figure script is
// a stand-in found where mhbench looks for it: the executable is copied into a scratch prefix
// beside share/mhbench/scripts/plot_study.py (runner/execution/companion_files.hpp), a script that
// starts a grandchild, writes both pids to a file and sleeps. PYTHONPATH holds an empty matplotlib
// package, which passes mhbench's `import matplotlib` probe, so the test needs no real one.
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "cli_harness.hpp"
#include "support/processes.hpp"

namespace {

namespace fs = std::filesystem;
using mhb::test_support::process_ended;
using mhb::test_support::wait_until;
using mhb::testing_cli::fresh;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;

// `words` run with `variable` (NAME=value) in the environment, its output in files in `dir`; its pid.
pid_t start(const std::vector<std::string>& words, const std::string& variable, const fs::path& dir) {
    std::vector<std::string> text = words;
    std::vector<char*> argv;
    for (auto& t : text)
        argv.push_back(t.data());
    argv.push_back(nullptr);
    std::vector<std::string> environment = {variable};
    const std::string name = variable.substr(0, variable.find('=') + 1);
    for (char** e = environ; *e != nullptr; ++e)
        if (!std::string(*e).starts_with(name))
            environment.emplace_back(*e);
    std::vector<char*> envp;
    for (auto& e : environment)
        envp.push_back(e.data());
    envp.push_back(nullptr);
    const std::string out = (dir / "report.stdout").string();
    const std::string err = (dir / "report.stderr").string();
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int out_fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (out_fd < 0 || err_fd < 0 || ::dup2(out_fd, 1) < 0 || ::dup2(err_fd, 2) < 0)
            ::_exit(127);
        ::execve(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    return pid;
}

TEST(FigureOrphans, SigkillDuringFiguresLeavesNeitherTheScriptNorWhatItStarted) {
    const fs::path dir = fresh("figure_orphans");
    const fs::path study = dir / "study";
    ASSERT_EQ(run_mhbench("run --algorithms random-search --problem sphere:dim=2 --runs 1 --evaluations 100 "
                          "--no-report --quiet --out '" +
                          study.string() + "'")
                  .exit_code,
              0);

    // The prefix: bin/mhbench, share/mhbench/scripts/plot_study.py, and the stand-in matplotlib.
    const fs::path prefix = dir / "prefix";
    fs::create_directories(prefix / "bin");
    fs::create_directories(prefix / "share" / "mhbench" / "scripts");
    fs::create_directories(prefix / "python" / "matplotlib");
    std::ofstream(prefix / "python" / "matplotlib" / "__init__.py") << "";
    fs::copy_file(MHB_CLI_PATH, prefix / "bin" / "mhbench");
    const fs::path pids = dir / "pids.txt";
    std::ofstream(prefix / "share" / "mhbench" / "scripts" / "plot_study.py")
        << "import os, subprocess, time\n"
        << "grandchild = subprocess.Popen(['/bin/sleep', '300'])\n"
        << "with open(" << pids << " + '.tmp', 'w') as f:\n"
        << "    f.write('%d %d\\n' % (os.getpid(), grandchild.pid))\n"
        << "os.rename(" << pids << " + '.tmp', " << pids << ")\n"
        << "time.sleep(300)\n";

    const pid_t mhbench = start({(prefix / "bin" / "mhbench").string(), "report", study.string()},
                                "PYTHONPATH=" + (prefix / "python").string(), dir);
    ASSERT_GT(mhbench, 0);
    const bool started = wait_until([&] { return fs::exists(pids); }, 60.0);
    if (!started)
        ::kill(mhbench, SIGKILL);
    ASSERT_TRUE(started) << read_text(dir / "report.stderr");
    pid_t script = 0;
    pid_t grandchild = 0;
    std::istringstream(read_text(pids)) >> script >> grandchild;
    ASSERT_GT(script, 0);
    ASSERT_GT(grandchild, 0);
    EXPECT_FALSE(process_ended(script));
    EXPECT_FALSE(process_ended(grandchild));

    ::kill(mhbench, SIGKILL);
    int status = 0;
    ::waitpid(mhbench, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    EXPECT_TRUE(wait_until([&] { return process_ended(script); }, 5.0))
        << "the figure script outlived mhbench";
    EXPECT_TRUE(wait_until([&] { return process_ended(grandchild); }, 5.0))
        << "the program the figure script started outlived mhbench";
    for (const pid_t left : {script, grandchild}) // whatever the outcome, nothing of the test stays
        if (!process_ended(left))
            ::kill(left, SIGKILL);
}

} // namespace
