// mhbench: benchmarking metaheuristic optimisers, starting from the paper study of
// Li, Wang and Ji (2017), "PMSM parameter identification based on improved TLBO".
#include <boost/program_options/errors.hpp>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <poll.h>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include "mhb_version.hpp"
#include "problems/core/text_excerpt.hpp"
#include "runner/cli/command.hpp"

namespace mhb::cli {

// One line per subcommand; each is defined in its own file.
int run_run_command(const std::vector<std::string>& args);
int run_list_command(const std::vector<std::string>& args);
int run_report_command(const std::vector<std::string>& args);
int run_simulate_command(const std::vector<std::string>& args);
int run_identify_command(const std::vector<std::string>& args);
int run_eval_command(const std::vector<std::string>& args);
int run_merge_command(const std::vector<std::string>& args);
int run_plan_command(const std::vector<std::string>& args);
int run_plugin_check_command(const std::vector<std::string>& args);

namespace {

const std::vector<Command>& commands() {
    static const std::vector<Command> table = {
        {"run", "run a study (algorithms x problems x runs) in parallel into a directory", run_run_command},
        {"list", "list algorithms, problems and study presets with their parameters", run_list_command},
        {"report", "tables, statistics, curve data and figures of a finished study", run_report_command},
        {"simulate", "simulate the paper's drive and write a dataset CSV", run_simulate_command},
        {"identify", "least-squares Rs, Ld, Lq, psi with standard errors from a dataset CSV",
         run_identify_command},
        {"eval", "print f at given points (check a function by hand)", run_eval_command},
        {"plan", "how many problems and runs a comparison needs (power, precision), before any run",
         run_plan_command},
        {"merge", "join the shard directories of one study (mhbench run --shard i/n) into one",
         run_merge_command},
        {"plugin-check", "check that an optimiser or a problem (your own: a plug-in) is fit for a study",
         run_plugin_check_command},
    };
    return table;
}

void print_usage(std::ostream& out) {
    out << "mhbench " << build::version << " — parallel benchmarking of metaheuristic optimisers\n\n"
        << "Usage: mhbench <command> [options]    (mhbench <command> --help for its options)\n\n"
        << "Commands:\n";
    for (const auto& c : commands()) {
        char line[160];
        std::snprintf(line, sizeof line, "  %-10s %s\n", c.name, c.summary);
        out << line;
    }
    out << "\nOptions:\n  --help     this text\n  --version  version and git commit\n";
}

// A write to a pipe whose reader is gone must fail (EPIPE) where it happens, not raise a SIGPIPE
// that ends mhbench without a word and loses its stdout: an external program that exits before
// reading all it was sent (problems/core/process/child_process.cpp), or a reader of mhbench's own
// stdout that stops early (`mhbench list | head -1`). Set first, before any thread exists; every
// child gets the default back before exec (problems/core/process/: every program mhbench starts),
// since an ignored signal stays ignored across exec.
void ignore_sigpipe() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, nullptr);
}

// Whether stdout is a pipe (or socket) that nobody reads any more.
bool stdout_reader_gone() {
    pollfd out{STDOUT_FILENO, POLLOUT, 0};
    return ::poll(&out, 1, 0) == 1 && (out.revents & POLLERR) != 0;
}

// The command's exit status, or a failure if its stdout could not be written: quietly when the
// reader has gone (it took what it wanted), with a line otherwise (a full disk).
int with_stdout_checked(int status) {
    std::cout.flush();
    const bool failed = !std::cout || std::fflush(stdout) != 0;
    if (!failed)
        return status;
    if (!stdout_reader_gone())
        std::cerr << "mhbench: cannot write to stdout\n";
    return status != exit_ok ? status : exit_failure;
}

int run_command(const Command& command, const std::vector<std::string>& args) {
    try {
        return command.run(args);
    } catch (const boost::program_options::error& e) {
        std::cerr << "mhbench " << command.name << ": " << e.what() << " (see mhbench " << command.name
                  << " --help)\n";
        return exit_usage;
    } catch (const std::invalid_argument& e) {
        std::cerr << "mhbench " << command.name << ": " << e.what() << '\n';
        return exit_usage;
    } catch (const std::exception& e) {
        std::cerr << "mhbench " << command.name << ": " << e.what() << '\n';
        return exit_failure;
    }
}

} // namespace
} // namespace mhb::cli

int main(int argc, char** argv) {
    using namespace mhb::cli;
    ignore_sigpipe();
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        print_usage(args.empty() ? std::cerr : std::cout);
        return with_stdout_checked(args.empty() ? exit_usage : exit_ok);
    }
    if (args[0] == "--version") {
        if (args.size() > 1) {
            std::cerr << "mhbench: --version takes no other argument (got '" << args[1] << "')\n";
            return mhb::cli::exit_usage;
        }
        std::cout << "mhbench " << mhb::build::version << " (commit " << mhb::build::git_commit << ", "
                  << mhb::build::compiler << ", " << mhb::build::build_type << ")\n";
        return with_stdout_checked(exit_ok);
    }
    for (const auto& command : commands())
        if (args[0] == command.name)
            return with_stdout_checked(
                run_command(command, std::vector<std::string>(args.begin() + 1, args.end())));
    std::cerr << "mhbench: unknown command " << mhb::quoted_excerpt(args[0])
              << "; run mhbench --help for the list\n";
    return exit_usage;
}
