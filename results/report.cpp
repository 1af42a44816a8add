#include "results/report.hpp"

#include <cstdlib>
#include <stdexcept>

#include "results/comparison_tables.hpp"
#include "results/critical_difference.hpp"
#include "results/csv.hpp"
#include "results/curve_data.hpp"
#include "results/ioh_export.hpp"
#include "results/paper_tables.hpp"
#include "results/study_index.hpp"
#include "results/table.hpp"

namespace mhb {

namespace fs = std::filesystem;

namespace {

// Single-quoted for /bin/sh (a quote inside becomes '\'').
std::string shell_quote(const std::string& text) {
    std::string out = "'";
    for (char c : text)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

void check_options(const ReportOptions& options) {
    if (!(options.alpha > 0.0 && options.alpha < 1.0))
        throw std::invalid_argument("--alpha = " + format_number(options.alpha) + " is outside (0, 1)");
    if (options.formats.empty())
        throw std::invalid_argument("--format: choose at least one of md, tex, csv");
    for (const auto& f : options.formats)
        if (f != "md" && f != "tex" && f != "csv")
            throw std::invalid_argument("--format: '" + f + "' is not one of md, tex, csv");
}

std::string latex_document(const std::vector<Table>& tables) {
    std::string out = "% All tables of the report; compiles with pdflatex (article + booktabs).\n"
                      "\\documentclass{article}\n\\usepackage{booktabs}\n"
                      "\\begin{document}\n";
    for (const auto& t : tables)
        out += render_latex(t) + "\n";
    return out + "\\end{document}\n";
}

void draw_figures(const ReportOptions& options, const fs::path& out_dir, std::ostream& console) {
    const std::string how =
        "install matplotlib (apt install python3-matplotlib) and run mhbench report again, or "
        "run scripts/plot_study.py " +
        out_dir.string();
    if (options.plot_script.empty() || !fs::exists(options.plot_script)) {
        console << "figures skipped: the plotting script " << options.plot_script.string()
                << " was not found; the tables and curve data are written\n";
        return;
    }
    const auto python = find_matplotlib_python(options.python_candidates);
    if (!python) {
        console << "figures skipped: no Python with matplotlib found; " << how << '\n';
        return;
    }
    const std::string command = shell_quote(*python) + " " + shell_quote(options.plot_script.string()) + " " +
                                shell_quote(out_dir.string());
    if (std::system(command.c_str()) != 0)
        throw std::runtime_error("the plotting script failed: " + command);
    console << "figures: " << (out_dir / "figures").string() << '\n';
}

} // namespace

std::optional<std::string> find_matplotlib_python(const std::vector<std::string>& candidates) {
    for (const auto& python : candidates) {
        const std::string probe = shell_quote(python) + " -c 'import matplotlib' >/dev/null 2>&1";
        if (std::system(probe.c_str()) == 0)
            return python;
    }
    return std::nullopt;
}

void build_report(const StudyData& study, const ReportOptions& options, std::ostream& console) {
    check_options(options);
    const StudyIndex index(study);
    ComparisonOptions comparison;
    comparison.reference = resolve_reference(index, options.reference);
    comparison.alpha = options.alpha;

    const fs::path out_dir = options.out_dir.empty() ? study.directory / "report" : options.out_dir;
    std::error_code ec;
    fs::create_directories(out_dir, ec);
    if (ec || !fs::is_directory(out_dir))
        throw std::runtime_error(out_dir.string() + ": cannot create the report directory");

    std::vector<Table> tables = pmsm_paper_tables(index);
    for (auto& t : comparison_tables(index, comparison))
        tables.push_back(std::move(t));

    const auto count = [](std::size_t n, const char* noun) {
        return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
    };
    console << "mhbench report of " << study.directory.string() << ": " << count(study.runs.size(), "run")
            << " (" << index.failed_runs() << " failed), " << count(index.problems().size(), "problem")
            << ", " << count(index.algorithms().size(), "algorithm") << "; reference " << comparison.reference
            << "\n\n";
    // The context (version, commit, compiler, threads, date) heads the combined report, so a table
    // read later says what produced it.
    std::string all_markdown = "# mhbench report: " + study.directory.string() +
                               "\n\nStudy context (context.ini):\n\n```\n" + study.context_text +
                               (study.context_text.empty() || study.context_text.back() == '\n' ? "" : "\n") +
                               "```\n\n";
    for (const auto& t : tables) {
        const std::string markdown = render_markdown(t);
        console << markdown << '\n';
        all_markdown += markdown + '\n';
        if (options.formats.count("md"))
            write_file_atomically(out_dir / (t.id + ".md"), markdown);
        if (options.formats.count("tex"))
            write_file_atomically(out_dir / (t.id + ".tex"), render_latex(t));
        if (options.formats.count("csv"))
            write_file_atomically(out_dir / (t.id + ".csv"), render_csv(t));
    }
    if (options.formats.count("md"))
        write_file_atomically(out_dir / "report.md", all_markdown);
    if (options.formats.count("tex"))
        write_file_atomically(out_dir / "report.tex", latex_document(tables));

    write_file_atomically(out_dir / "curves_iteration.csv", fitness_curves_by_iteration(index));
    write_file_atomically(out_dir / "curves_evaluations.csv", fitness_curves_by_evaluations(index));
    write_file_atomically(out_dir / "parameters_iteration.csv", parameter_curves_by_iteration(index));
    write_file_atomically(out_dir / "final_values.csv", final_values(index));
    write_file_atomically(out_dir / "target_hits.csv", target_hits(index));
    const fs::path cd_path = out_dir / "critical_difference.csv";
    if (const auto cd = critical_difference_data(index, options.alpha))
        write_file_atomically(cd_path, *cd);
    else
        fs::remove(cd_path, ec); // a stale one from an earlier report would mislead
    const std::size_t ioh_files = write_ioh_export(index, out_dir / "ioh");
    console << "tables and curve data: " << out_dir.string() << "\nIOHprofiler export (" << ioh_files
            << " files, load the folder in IOHanalyzer): " << (out_dir / "ioh").string() << '\n';
    if (options.figures)
        draw_figures(options, out_dir, console);
}

} // namespace mhb
