// The figures of a report: finding a Python with matplotlib and running plot_study.py (see
// report_figures.hpp).
#include "results/report/report_figures.hpp"

#include <optional>
#include <sys/wait.h>
#include <vector>

#include "results/report/child_process.hpp"
#include "results/store/csv.hpp"

namespace mhb {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> non_empty_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        std::string line = text.substr(start, end - start);
        if (line.find_first_not_of(" \t\r") != std::string::npos)
            lines.push_back(std::move(line));
        start = end + 1;
    }
    return lines;
}

// The first candidate that can import matplotlib; `interrupted` when a stop came meanwhile.
std::optional<std::string> find_python(const std::vector<std::string>& candidates, bool& interrupted) {
    interrupted = false;
    for (const auto& python : candidates) {
        const ChildOutcome probe = run_child_process(python, {"-c", "import matplotlib"}, false);
        if (probe.stop_requested) {
            interrupted = true;
            return std::nullopt;
        }
        if (probe.exited_with(0))
            return python;
    }
    return std::nullopt;
}

// The exit status plot_study.py gives when SIGINT or SIGTERM stopped it (as a shell reports Ctrl-C).
constexpr int plot_exit_interrupted = 130;
// ... and when the Python that runs it cannot import matplotlib: the next candidate is tried. The
// script is its own probe: a separate `python -c "import matplotlib"` first cost a third of a second
// of every report (issue 37).
constexpr int plot_exit_no_matplotlib = 3;

// The script run by the first candidate Python that can import matplotlib; nullopt when none can.
std::optional<ChildOutcome> run_plot_script(const ReportOptions& options, const fs::path& out_dir) {
    for (const auto& python : options.python_candidates) {
        ChildOutcome run = run_child_process(python, {options.plot_script.string(), out_dir.string()}, true);
        if (run.stop_requested || (run.started && !run.exited_with(plot_exit_no_matplotlib)))
            return run;
    }
    return std::nullopt;
}

} // namespace

Figures draw_figures(const ReportOptions& options, const fs::path& out_dir, std::ostream& console,
                     std::string& note) {
    note.clear();
    if (options.stop != nullptr && options.stop->load())
        return Figures::interrupted;
    const std::string how =
        "install matplotlib (apt install python3-matplotlib) and run mhbench report again, or "
        "run " +
        options.plot_script.string() + " " + out_dir.string();
    if (options.plot_script.empty() || !fs::exists(options.plot_script)) {
        console << "figures skipped: the plotting script " << options.plot_script.string()
                << " was not found; the tables and curve data are written\n";
        note = "figures skipped: the plotting script " + options.plot_script.string() + " was not found";
        return Figures::drawn_or_skipped;
    }
    // The script's output is collected, not passed through: its notes (what a figure left out) go to
    // the console, a figure that failed is one line on `errors`, and a traceback stays in a log.
    const fs::path figures = out_dir / "figures";
    std::error_code ec;
    fs::create_directories(figures, ec);
    const fs::path log_file = figures / "plot_study.log";
    const std::optional<ChildOutcome> ran = run_plot_script(options, out_dir);
    if (!ran) {
        fs::remove(figures, ec); // only if empty: an earlier report's figures stay
        console << "figures skipped: no Python with matplotlib found; " << how << '\n';
        note = "figures skipped: no Python with matplotlib found; " + how;
        return Figures::drawn_or_skipped;
    }
    const ChildOutcome& run = *ran;
    fs::remove(log_file, ec); // a stale log from an earlier report would mislead
    if (run.stop_requested || run.exited_with(plot_exit_interrupted))
        return Figures::interrupted; // the figures drawn so far are whole; the next report redraws all
    const bool succeeded = run.exited_with(0);
    for (const auto& line : non_empty_lines(run.out))
        console << line << '\n';
    if (!succeeded || !run.err.empty()) // keep everything the script said, traceback included
        write_file_atomically(log_file, run.started ? run.out + run.err : run.error + '\n');
    std::ostream& errors = *options.errors;
    if (!succeeded) {
        const auto lines = non_empty_lines(run.err.empty() ? run.out : run.err);
        std::string reason = lines.empty() ? std::string("no output") : lines.back();
        if (!run.started)
            reason = "the plotting script did not finish (could not start: " + run.error + ")";
        else if (!WIFEXITED(run.status))
            reason = "the plotting script did not finish (" +
                     (WIFSIGNALED(run.status) ? "signal " + std::to_string(WTERMSIG(run.status))
                                              : std::string("status ") + std::to_string(run.status)) +
                     ")";
        errors << "figures failed: " << reason << " (full output: " << log_file.string()
               << "); the tables and curve data are written\n";
        note = "figures failed: " + reason + " (full output: figures/plot_study.log)";
        return Figures::drawn_or_skipped;
    }
    const auto failures = non_empty_lines(run.err);
    for (const auto& line : failures) // the script's one line per figure that failed
        errors << "figures: " << line << '\n';
    if (!failures.empty())
        note = "some figures could not be drawn (" + failures.front() + (failures.size() > 1 ? ", ..." : "") +
               ")";
    // A report of several budgets draws into each budget's folder: the top folder's stays empty.
    if (fs::is_empty(figures, ec) && !ec) {
        fs::remove(figures, ec);
        console << "figures: " << (out_dir / "<budget>" / "figures").string() << '\n';
    } else {
        console << "figures: " << figures.string() << '\n';
    }
    return Figures::drawn_or_skipped;
}

std::optional<std::string> find_matplotlib_python(const std::vector<std::string>& candidates) {
    bool interrupted = false;
    return find_python(candidates, interrupted);
}

} // namespace mhb
