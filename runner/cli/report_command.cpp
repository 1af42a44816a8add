// `mhbench report DIR`: rebuilds every table, the curve data and the figures of a finished study
// from its directory alone. Thin: parses the command line, loads the study, calls build_report.
#include <algorithm>
#include <boost/program_options.hpp>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "problems/core/process/detached_program.hpp"
#include "problems/core/process/executable_path.hpp"
#include "results/html/html_report.hpp"
#include "results/report/report.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_files.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/format_option.hpp"
#include "runner/cli/parse_command_line.hpp"
#include "runner/cli/rope_option.hpp"
#include "runner/execution/companion_files.hpp"
#include "runner/execution/study_lock.hpp"

namespace mhb::cli {

namespace po = boost::program_options;

namespace {

// --open: the page in the desktop's browser, when there is a desktop. Never an error: without a
// display or xdg-open the path printed above is all the user needs. xdg-open runs detached (its
// own session, output discarded, not waited for), so a browser that stays open does not keep
// `mhbench report` waiting, and a browser's complaints do not mix with the report.
void open_in_browser(const std::filesystem::path& page) {
    const bool display = std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr;
    const std::string opener = display ? process::find_executable("xdg-open").value_or("") : "";
    if (opener.empty()) {
        std::cout << "--open: "
                  << (display ? "xdg-open not found" : "no display (DISPLAY and WAYLAND_DISPLAY unset)")
                  << "; open " << file_url(page) << " in a browser\n";
        return;
    }
    const std::string url = file_url(page);
    std::cout << "--open: opening " << url << " with xdg-open\n";
    std::cout.flush();
    process::start_detached({opener, url});
}

// Whether `dir` holds a study's records (finished or not): a report written there would
// replace some of them (its algorithms.csv is not the study's).
bool holds_study_records(const std::filesystem::path& dir) {
    std::error_code ec;
    for (const char* record :
         {StudyFiles::marker, StudyFiles::study, StudyFiles::runs, StudyFiles::store, StudyFiles::journal})
        if (std::filesystem::exists(dir / record, ec))
            return true;
    return false;
}

// Whether `inner` is `outer` or lies below it, symbolic links and ".." resolved.
bool is_within(const std::filesystem::path& inner, const std::filesystem::path& outer) {
    std::error_code ec;
    const std::filesystem::path a = std::filesystem::weakly_canonical(std::filesystem::absolute(inner), ec);
    const std::filesystem::path b = std::filesystem::weakly_canonical(std::filesystem::absolute(outer), ec);
    const auto [end_b, at_a] = std::mismatch(b.begin(), b.end(), a.begin(), a.end());
    return end_b == b.end() || (std::next(end_b) == b.end() && end_b->empty()); // "dir/" ends in ""
}

// The command line's values, as given.
struct ReportCommandLine {
    std::string study_dir;
    std::string out_dir;
    std::string reference;
    std::string formats = default_format_option();
    double alpha = 0.05;
    std::string ioh_precision = "ioh";
};

po::options_description report_options(ReportCommandLine& given) {
    po::options_description visible(
        "Usage: mhbench report DIR [options]\n\n"
        "Rebuilds, from the study directory DIR alone, the report in DIR/report/:\n"
        "  - for PMSM problems: fitness (mean/std, evaluations spent, gap to the least-squares optimum\n"
        "    f*), identified parameters (% errors, the least-squares theta*) and, with several operating\n"
        "    conditions, the conditions side by side; a study with protocol = pmsm-paper (the paper\n"
        "    presets) gets them as the paper's Tables 2-4 beside the published values at 150 iterations;\n"
        "  - for every problem: summary statistics, ERT, medians at 1/10/100% of one evaluation count\n"
        "    per problem (the same for every algorithm); Wilcoxon rank-sum (and, for paired runs,\n"
        "    signed-rank) tests against a reference with Holm correction and Vargha-Delaney A12; the\n"
        "    problems-by-algorithms table of medians (IQR) with the tests' +/=/- markers and w/t/l\n"
        "    counts; Friedman ranks and Wilcoxon signed-rank across problems; the Bayesian signed-rank\n"
        "    test (P(reference better), P(equivalent within --rope), P(algorithm better));\n"
        "  - each table as Markdown, CSV and LaTeX (laid out to fit a journal's page; report.tex holds\n"
        "    them all and compiles with pdflatex and TeX Live's latex-base and latex-recommended);\n"
        "  - curve data (CSV) and figures (PDF for a paper and PNG, needs matplotlib: apt install\n"
        "    python3-matplotlib);\n"
        "  - index.html: the verdict of each budget first, the key figures (convergence, final values),\n"
        "    then every table (sortable by a click on a header) and figure (the PNG files, each linking\n"
        "    to its PDF) and the study's context last; a page per budget (budget_<slug>.html) when there\n"
        "    are several; no network, no other file outside the report. Its path is printed at the end.\n"
        "Printed here: the verdict of each budget (per problem the algorithms ranked by median, each\n"
        "against the best; across problems the mean ranks; the components of a factorial design), in\n"
        "one screen; --tables prints every table in Markdown too.\n\nOptions");
    visible.add_options()("help,h", "this text")(
        "out", po::value(&given.out_dir),
        "report directory (default: DIR/report); never a study directory (refused: the report would "
        "replace its records), and refused inside DIR while another process writes the study")(
        "reference", po::value(&given.reference),
        "algorithm the tests compare against: a full spec or a name of the study (default: itlbo, else the "
        "first algorithm)")("alpha", po::value(&given.alpha)->default_value(0.05, "0.05"),
                            "significance level of the +/=/- markers, in (0, 1)")(
        "rope", po::value<double>()->default_value(default_log10_rope, format_number(default_log10_rope)),
        rope_option_help)("raw-rope", po::value<double>(), raw_rope_option_help)(
        "no-figures", "write tables and curve data only (index.html says so; it shows figures an earlier "
                      "report drew, marked as such)")(
        "open", "print index.html's path and open it in a browser (xdg-open) when a display is available")(
        "quiet,q", "print nothing but warnings and errors (the report is written all the same)")(
        "tables", "print every table in Markdown before the verdict (the files hold them either way)")(
        "format", po::value(&given.formats)->default_value(given.formats), format_option_help().c_str())(
        "ioh-precision", po::value(&given.ioh_precision)->default_value(given.ioh_precision),
        "raw_y in the IOHprofiler export (ioh/*.dat): ioh = %.10f, what IOHexperimenter writes (an error "
        "below 5e-11 reads 0); full = every digit (1.234e-12), which IOHanalyzer reads too");
    return visible;
}

// The report's options from the command line's (--ioh-precision checked already).
ReportOptions report_options_of(const ReportCommandLine& given, const po::variables_map& vm) {
    ReportOptions options;
    options.out_dir = given.out_dir;
    options.ioh_precision = given.ioh_precision == "full" ? IohPrecision::full : IohPrecision::logger;
    if (!given.reference.empty())
        options.reference = given.reference;
    options.alpha = given.alpha;
    set_rope_options(vm, options);
    options.figures = vm.count("no-figures") == 0;
    options.console_tables = vm.count("tables") != 0;
    options.formats = parse_format_option(given.formats);
    options.plot_script = companion_file("scripts/plot_study.py");
    return options;
}

// The report of the study in `study_dir` into `report_dir`, printed unless `quiet`, and opened when
// asked.
int write_report(const std::string& study_dir, const std::filesystem::path& report_dir,
                 const ReportOptions& options, bool open, bool quiet) {
    if (holds_study_records(report_dir)) {
        std::cerr << "mhbench report: --out " << report_dir.string()
                  << " is a study directory, and a report would replace its records; leave --out out "
                     "(the report goes to DIR/report) or name a directory of its own\n";
        return exit_failure;
    }
    // Reading needs no lock (a study's files are each replaced whole, runs.csv last), but writing
    // into the study does: the process that holds it may replace or remove what is written.
    std::optional<StudyLock> lock;
    if (std::filesystem::is_directory(study_dir) && is_within(report_dir, study_dir)) {
        try {
            lock.emplace(study_dir, "mhbench report");
        } catch (const StudyInUse& e) {
            std::cerr << "mhbench report: " << e.what()
                      << "; wait for it, or give --out a directory outside the study\n";
            return exit_failure;
        }
    }
    const StudyData study = load_study(study_dir);
    for (const std::string& warning : study.warnings)
        std::cerr << "mhbench report: warning: " << warning << '\n';
    // A report that fails prints nothing and leaves no report folder it made (its files are each
    // written whole, so a folder that existed holds whole files only).
    std::error_code ec;
    const bool existed = std::filesystem::exists(report_dir, ec);
    std::ostringstream printed;
    ReportOutcome outcome;
    try {
        outcome = build_report(study, options, printed);
    } catch (...) {
        if (!existed)
            std::filesystem::remove_all(report_dir, ec);
        throw;
    }
    if (!quiet)
        std::cout << printed.str();
    if (open)
        open_in_browser(outcome.html);
    // Ctrl-C during the figures: the tables are written, build_report said so in one line on stderr.
    return outcome.interrupted ? exit_interrupted : exit_ok;
}

} // namespace

int run_report_command(const std::vector<std::string>& args) {
    ReportCommandLine given;
    const po::options_description visible = report_options(given);
    po::options_description hidden;
    hidden.add_options()("study", po::value(&given.study_dir));
    po::options_description all;
    all.add(visible).add(hidden);
    po::positional_options_description positional;
    positional.add("study", 1);
    po::variables_map vm;
    if (!parse_command_line(
            args, all, vm, [&] { std::cout << visible << '\n'; }, &positional))
        return exit_ok;
    if (given.study_dir.empty()) {
        std::cerr << "mhbench report: give the study directory (mhbench report DIR; see --help)\n";
        return exit_usage;
    }
    if (given.ioh_precision != "ioh" && given.ioh_precision != "full") {
        std::cerr << "mhbench report: --ioh-precision '" << given.ioh_precision.substr(0, 40)
                  << "' is not one of ioh, full\n";
        return exit_usage;
    }
    const std::filesystem::path report_dir = given.out_dir.empty()
                                                 ? std::filesystem::path(given.study_dir) / "report"
                                                 : std::filesystem::path(given.out_dir);
    return write_report(given.study_dir, report_dir, report_options_of(given, vm), vm.count("open") != 0,
                        vm.count("quiet") != 0);
}

} // namespace mhb::cli
