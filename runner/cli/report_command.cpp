// `mhbench report DIR`: rebuilds every table, the curve data and the figures of a finished study
// from its directory alone. Thin: parses the command line, loads the study, calls build_report.
#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "results/report.hpp"
#include "results/store.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"

namespace mhb::cli {

namespace po = boost::program_options;

int run_report_command(const std::vector<std::string>& args) {
    std::string study_dir;
    std::string out_dir;
    std::string reference;
    std::string formats = "md,tex,csv";
    double alpha = 0.05;
    po::options_description visible(
        "Usage: mhbench report DIR [options]\n\n"
        "Rebuilds, from the study directory DIR alone, the report in DIR/report/:\n"
        "  - for PMSM problems, the paper's tables (Li, Wang, Ji 2017, ITLBO): Table 2 (fitness mean/std\n"
        "    beside the published values, evaluations spent, gap to the least-squares optimum f*),\n"
        "    Table 3 (identified parameters, % errors, the least-squares theta*) and Table 4 (conditions);\n"
        "  - for every problem: summary statistics, ERT, values at 1/10/100% of the budget; Wilcoxon\n"
        "    rank-sum tests against a reference with Holm correction and Vargha-Delaney A12; the\n"
        "    problems-by-algorithms table with +/=/- markers; Friedman ranks and Wilcoxon signed-rank\n"
        "    across problems;\n"
        "  - curve data (CSV) and figures (PDF/PNG, needs matplotlib: apt install python3-matplotlib).\n"
        "The Markdown tables are also printed here.\n\nOptions");
    visible.add_options()("help,h", "this text")("out", po::value(&out_dir),
                                                 "report directory (default: DIR/report)")(
        "reference", po::value(&reference),
        "algorithm the tests compare against: a full spec or a name of the study (default: itlbo, else the "
        "first algorithm)")("alpha", po::value(&alpha)->default_value(0.05, "0.05"),
                            "significance level of the +/=/- markers, in (0, 1)")(
        "no-figures", "write tables and curve data only")(
        "format", po::value(&formats)->default_value(formats), "table formats to write: any of md,tex,csv");
    po::options_description hidden;
    hidden.add_options()("study", po::value(&study_dir));
    po::options_description all;
    all.add(visible).add(hidden);
    po::positional_options_description positional;
    positional.add("study", 1);
    po::variables_map vm;
    if (!parse_command_line(
            args, all, vm, [&] { std::cout << visible << '\n'; }, &positional))
        return exit_ok;
    if (study_dir.empty()) {
        std::cerr << "mhbench report: give the study directory (mhbench report DIR; see --help)\n";
        return exit_usage;
    }
    ReportOptions options;
    options.out_dir = out_dir;
    if (!reference.empty())
        options.reference = reference;
    options.alpha = alpha;
    options.figures = vm.count("no-figures") == 0;
    options.formats.clear();
    std::stringstream list(formats);
    for (std::string f; std::getline(list, f, ',');) {
        const auto first = f.find_first_not_of(' ');
        if (first != std::string::npos) // "md, tex" is meant as "md,tex"
            options.formats.insert(f.substr(first, f.find_last_not_of(' ') - first + 1));
    }
    options.plot_script = std::filesystem::path(MHB_SOURCE_DIR) / "scripts" / "plot_study.py";
    const StudyData study = load_study(study_dir);
    // A report that fails prints nothing and leaves no report folder it made (its files are each
    // written whole, so a folder that existed holds whole files only).
    const std::filesystem::path report_dir =
        out_dir.empty() ? study.directory / "report" : std::filesystem::path(out_dir);
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
    std::cout << printed.str();
    // Ctrl-C during the figures: the tables are written, build_report said so in one line on stderr.
    return outcome.interrupted ? exit_interrupted : exit_ok;
}

} // namespace mhb::cli
