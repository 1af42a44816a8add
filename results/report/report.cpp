// The top room of results/: it includes every other room, since it alone knows the order in which a
// report is made (results/README.md draws the rooms).
#include "results/report/report.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <optional>
#include <stdexcept>

#include "results/analysis/bayesian_effects.hpp"
#include "results/analysis/cec_protocol.hpp" // study_protocol: the `protocol =` line of study.ini
#include "results/analysis/critical_difference.hpp"
#include "results/analysis/curve_data.hpp"
#include "results/analysis/factorial_effects.hpp"
#include "results/analysis/relative_gaps.hpp"
#include "results/analysis/run_precision.hpp"
#include "results/analysis/structural_bias.hpp"
#include "results/analysis/verdict.hpp"
#include "results/protocols/protocol_report.hpp"
#include "results/report/report_figures.hpp"
#include "results/report/report_readme.hpp"
#include "results/reporters/count_of.hpp"
#include "results/reporters/reporter_registry.hpp"
#include "results/store/csv.hpp"
#include "results/store/study_index.hpp"
#include "results/table_model/table.hpp"
#include "results/tables/anytime_tables.hpp"
#include "results/tables/bayesian_table.hpp"
#include "results/tables/comparison_tables.hpp"
#include "results/tables/effects_table.hpp"
#include "results/tables/overhead_table.hpp"
#include "results/tables/paper_tables.hpp"
#include "results/tables/precision_table.hpp"
#include "results/tables/relative_gap_table.hpp"
#include "results/tables/structural_bias_table.hpp"
#include "results/tables/verdict_tables.hpp"

namespace mhb {

namespace fs = std::filesystem;

namespace {

// Theta samples kept per Bayesian test for the simplex figures (of the 50 000 drawn): enough to
// show the cloud's shape, few enough to keep bayesian_samples.csv small.
constexpr std::size_t bayesian_figure_samples = 300;

// As typed in a shell: as it is when that is safe, else single-quoted (a quote inside becomes '\'').
std::string shell_quote(const std::string& text) {
    if (!text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                "0123456789_-+=.,:/@%") == std::string::npos)
        return text;
    std::string out = "'";
    for (char c : text)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

void check_options(const ReportOptions& options) {
    if (!(options.alpha > 0.0 && options.alpha < 1.0))
        throw std::invalid_argument("--alpha = " + format_number(options.alpha) + " is outside (0, 1)");
    const auto outside = [](const char* name, double value) {
        return std::string("--") + name + " = " +
               (std::isnan(value) ? std::string("nan") : format_number(value)) + " is outside [0, inf)";
    };
    if (!(options.rope >= 0.0) || !std::isfinite(options.rope))
        throw std::invalid_argument(outside("rope", options.rope));
    if (options.raw_rope && (!(*options.raw_rope >= 0.0) || !std::isfinite(*options.raw_rope)))
        throw std::invalid_argument(outside("raw-rope", *options.raw_rope));
    if (const std::optional<std::string> error = table_format_error(options.formats))
        throw std::invalid_argument(*error);
    if (options.errors == nullptr)
        throw std::logic_error("ReportOptions::errors is null");
}

// The tables of one budget, titled and captioned with it when it is known.
std::vector<Table> budget_tables(const StudyIndex& index, const ComparisonOptions& comparison,
                                 const std::vector<DesignEffects>& designs,
                                 const std::vector<DesignCandidate>& rejected, bool list_algorithms,
                                 const std::vector<const SuiteProtocol*>& protocols,
                                 const std::optional<RelativeGaps>& gaps,
                                 const std::optional<PrecisionRule>& precision,
                                 const std::vector<BayesianComparison>& bayesian, const BayesianRope& rope,
                                 const std::map<std::int64_t, double>& wall_seconds) {
    std::vector<Table> tables;
    if (list_algorithms) {
        Table t;
        t.id = "algorithms";
        t.title = "Algorithms";
        t.header = {"Label", "Spec", "Full spec"};
        for (const auto& a : index.algorithms())
            t.add_row({text_cell(index.label(a)), text_cell(a), text_cell(index.full_spec(a))});
        t.caption =
            "The label names the algorithm in every table and figure; the spec is canonical (defaults "
            "dropped), the full spec lists every parameter with its value, defaults included.";
        tables.push_back(std::move(t));
    }
    // A PMSM problem's own tables, unless a protocol frames them (the paper's, at its budget).
    if (std::none_of(protocols.begin(), protocols.end(),
                     [&](const SuiteProtocol* p) { return p->replaces_pmsm_tables(index); }))
        for (auto& t : pmsm_tables(index))
            tables.push_back(std::move(t));
    for (auto& t : protocol_tables(protocols, ProtocolTablesPlace::before_comparisons, index,
                                   comparison.reference, comparison.alpha))
        tables.push_back(std::move(t));
    for (auto& t : comparison_tables(index, comparison))
        tables.push_back(std::move(t));
    if (auto t = bayesian_table(index, comparison.reference, bayesian, rope)) // beside the tests
        tables.push_back(std::move(*t));
    if (gaps) // problems on one scale: where the optimisers part
        tables.push_back(relative_gap_table(index, *gaps));
    if (auto runs = precision_table(index, precision)) // runs = auto: what each cell took
        tables.push_back(std::move(*runs));
    // The protocols' tables that follow the statistics: the competition's, per dimension.
    for (auto& t : protocol_tables(protocols, ProtocolTablesPlace::after_comparisons, index,
                                   comparison.reference, comparison.alpha))
        tables.push_back(std::move(t));
    if (auto effects = effects_table(designs, rejected, comparison.alpha))
        tables.push_back(std::move(*effects));
    if (auto bias = structural_bias_table(index, comparison.alpha)) // f0: where the final points lie
        tables.push_back(std::move(*bias));
    // Anytime measures: the area under the ECDF of targets, the ERT per target with COCO's
    // bootstrap, and the time per evaluation where the study has timings.
    for (auto& t : {ecdf_area_table(index), ert_table(index), overhead_table(index, wall_seconds)})
        if (t)
            tables.push_back(*t);
    if (!index.budget().empty())
        for (auto& t : tables) {
            t.title += " [budget " + index.budget() + "]";
            t.caption += " Budget: " + index.budget() + ".";
            if (!t.latex_note.empty())
                t.latex_note += " Budget: " + index.budget() + ".";
        }
    return tables;
}

// The reference of one budget: the requested one if that budget ran it, else the default there.
std::string budget_reference(const StudyIndex& index, const ReportOptions& options, std::ostream& console) {
    if (options.reference) {
        try {
            return resolve_reference(index, options.reference);
        } catch (const std::invalid_argument&) {
            const std::string fallback = resolve_reference(index, std::nullopt);
            console << "budget " << index.budget() << ": --reference " << *options.reference
                    << " did not run at this budget; reference " << fallback << " instead\n";
            return fallback;
        }
    }
    return resolve_reference(index, std::nullopt);
}

void make_report_directory(const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw std::runtime_error(dir.string() + ": cannot create the report directory");
}

// The 2^k on/off designs among the budget's variants, with their effects, and the candidates that
// are not one (with why not).
struct FactorialFindings {
    std::vector<DesignEffects> designs;
    std::vector<DesignCandidate> rejected;
};

FactorialFindings factorial_findings(const StudyIndex& index, double alpha, double rope) {
    FactorialFindings found;
    for (auto& candidate : find_factorial_designs(index)) {
        if (!candidate.design) {
            found.rejected.push_back(std::move(candidate));
            continue;
        }
        DesignEffects effects{*candidate.design, factorial_effects(index, *candidate.design, alpha)};
        if (!effects.analyses.empty())
            found.designs.push_back(std::move(effects));
    }
    add_bayesian_effects(found.designs, rope);
    return found;
}

// Why runs failed: each distinct message once, with how many runs it ended and the first of them
// (a study of 10^4 runs that one fault failed 300 times says so in one line), and what to do.
void say_failures(const StudyIndex& index, std::ostream& console) {
    std::vector<std::pair<std::string, std::vector<const RunRecord*>>> reasons; // in order of first run
    for (const RunRecord* r : index.failed()) {
        const std::string why = r->message.empty() ? std::string("no message") : r->message;
        auto same =
            std::find_if(reasons.begin(), reasons.end(), [&](const auto& e) { return e.first == why; });
        if (same == reasons.end())
            reasons.push_back({why, {r}});
        else
            same->second.push_back(r);
    }
    console << count_of(index.failed().size(), "failed run")
            << " left out (running the study's command again "
            << "computes them again, keeping every other run):\n";
    constexpr std::size_t shown = 3;
    for (std::size_t i = 0; i < reasons.size() && i < shown; ++i)
        console << "  " << count_of(reasons[i].second.size(), "run")
                << " (first: " << run_name(index, *reasons[i].second.front()) << "): " << reasons[i].first
                << '\n';
    if (reasons.size() > shown)
        console << "  and " << reasons.size() - shown << " other reasons: runs.csv, column 'message'\n";
}

// The console's summary of a budget: its runs, what was left out, and its factorial designs.
void say_budget_summary(const StudyData& study, const std::string& budget, const StudyIndex& index,
                        const std::string& heading, const std::string& reference,
                        const FactorialFindings& factorial, std::ostream& console) {
    std::size_t runs = 0;
    for (const auto& r : study.runs)
        runs += r.budget == budget ? 1U : 0U;
    console << heading << count_of(runs, "run") << " (" << index.failed_runs() << " failed), "
            << count_of(index.problems().size(), "problem") << ", "
            << count_of(index.algorithms().size(), "algorithm") << "; reference " << index.label(reference)
            << '\n';
    if (!index.failed().empty())
        say_failures(index, console);
    if (index.infinite_runs() > 0)
        console << count_of(index.infinite_runs(), "run") << " ended at "
                << (index.negative_infinite_runs() == 0 ? "+inf" : "+inf or -inf")
                << ": the worst value in medians and rank tests, inf in means\n";
    if (const std::optional<PrecisionRule> rule = precision_rule_of(study.study_text))
        console << precision_summary(index, *rule) << '\n';
    for (const auto& d : factorial.designs)
        console << "factorial design " << d.design.description() << ": effects in effects.csv\n";
    for (const auto& r : factorial.rejected)
        console << "no factorial analysis of " << r.name << ": " << r.why_not << '\n';
}

// The protocols the study follows: the one study.ini names (`protocol = cec2017`, `pmsm-paper`), if
// this mhbench knows it, and those in force unnamed. They add tables and files.
std::vector<const SuiteProtocol*> study_protocols(const StudyData& study, std::ostream& console) {
    const std::optional<std::string> protocol_name = study_protocol(study.study_text);
    if (protocol_name && find_protocol(*protocol_name) == nullptr)
        console << "protocol '" << *protocol_name << "' is not one this mhbench knows (" << protocol_names()
                << "): its tables and result files are not written\n";
    return protocols_in_force(protocol_name.value_or(""));
}

// Writes `content` to `path`, or removes `path` when there is none: a stale file from an earlier
// report would mislead.
void write_or_remove(const fs::path& path, const std::optional<std::string>& content) {
    std::error_code ec;
    if (content)
        write_file_atomically(path, *content);
    else
        fs::remove(path, ec);
}

// The files of the optional tables `ids` that this report did not make: stale copies would mislead.
void remove_absent_tables(const fs::path& dir, const std::vector<Table>& tables,
                          std::initializer_list<const char*> ids) {
    std::error_code ec;
    for (const char* id : ids)
        if (std::none_of(tables.begin(), tables.end(), [&](const Table& t) { return t.id == id; }))
            for (const std::string& format : table_format_names())
                fs::remove(dir / (std::string(id) + "." + format), ec);
}

// The budget's curve data and statistics for the figures, and budget.txt; says which of the
// optional files were written.
void write_curve_data(const StudyIndex& index, const std::string& budget, const fs::path& dir,
                      const std::vector<DesignEffects>& designs, const std::optional<RelativeGaps>& gaps,
                      double alpha, ReportFiles& files) {
    write_or_remove(dir / "budget.txt",
                    budget.empty() ? std::nullopt : std::optional<std::string>(budget + "\n"));
    write_file_atomically(dir / "curves_iteration.csv", fitness_curves_by_iteration(index));
    write_file_atomically(dir / "curves_evaluations.csv", fitness_curves_by_evaluations(index));
    write_file_atomically(dir / "parameters_iteration.csv", parameter_curves_by_iteration(index));
    write_file_atomically(dir / "final_values.csv", final_values(index));
    write_file_atomically(dir / "problems.csv", problem_facts(index));
    write_file_atomically(dir / "target_hits.csv", target_hits(index));
    const std::optional<std::string> critical_difference = critical_difference_data(index, alpha);
    write_or_remove(dir / "critical_difference.csv", critical_difference);
    write_or_remove(dir / "effect_means.csv",
                    designs.empty() ? std::nullopt : std::optional<std::string>(effect_means_csv(designs)));
    write_or_remove(dir / "relative_gap_medians.csv",
                    gaps ? std::optional<std::string>(relative_gap_medians_csv(index, *gaps)) : std::nullopt);
    const std::optional<std::string> final_points = final_points_csv(index); // f0's structural bias
    write_or_remove(dir / "final_points.csv", final_points);
    files.final_points = final_points.has_value();
    write_or_remove(dir / "uniformity_tests.csv", uniformity_tests_csv(index, alpha));
    std::error_code ec;
    // Tables a report may leave out: stale copies from an earlier report would mislead.
    for (const std::string& format : table_format_names()) {
        if (designs.empty())
            fs::remove(dir / ("effects." + format), ec);
        if (!gaps)
            fs::remove(dir / ("relative_gaps." + format), ec);
        if (!files.final_points)
            fs::remove(dir / ("structural_bias." + format), ec);
    }
    files.critical_difference = critical_difference.has_value();
    files.effect_means = !designs.empty();
    files.relative_gaps = gaps.has_value();
    files.budget_txt = !budget.empty();
}

// The folders of the budgets, in order.
std::vector<std::string> folders_of(const std::vector<BudgetSection>& sections) {
    std::vector<std::string> folders;
    for (const auto& section : sections)
        folders.push_back(section.folder);
    return folders;
}

// PMSM tables an earlier report wrote under another name (the paper's Table 2 at another budget, or
// a neutral table the paper's framing now replaces): stale copies would mislead.
void remove_stale_pmsm_tables(const fs::path& dir, const std::vector<Table>& tables) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string stem = entry.path().stem().string();
        const std::string extension = entry.path().extension().string();
        const auto formats = table_format_names();
        const bool table_file = extension.size() > 1 && std::find(formats.begin(), formats.end(),
                                                                  extension.substr(1)) != formats.end();
        const bool current =
            std::any_of(tables.begin(), tables.end(), [&](const Table& t) { return t.id == stem; });
        if (table_file && !current && is_pmsm_table_id(stem))
            fs::remove(entry.path(), ec);
    }
}

// The figures of the budget unless `figures` is false (set to false when they are interrupted),
// and what the budget's section of the study-level documents (index.html) says about them.
void draw_budget_figures(const ReportOptions& options, const fs::path& dir, std::ostream& console,
                         bool& figures, BudgetSection& html) {
    html.figures_current = figures;
    if (figures && draw_figures(options, dir, console, html.figures_note) == Figures::interrupted)
        figures = false;
    if (!figures) {
        html.figures_current = false;
        html.figures_note = options.figures
                                ? "the figures were interrupted; run mhbench report on the study to "
                                  "draw them"
                                : "the figures were not drawn (--no-figures)";
    }
}

// The budget's README.md, once its figures are drawn (or not): it lists what the folder holds.
void write_budget_readme(const fs::path& dir, const BudgetSection& section, ReportFiles files) {
    files.figures = fs::exists(dir / "figures");
    write_file_atomically(dir / "README.md", report_readme(section.tables, files));
}

// Everything of one budget in `dir` but its figures: tables, curve data, effects, what every
// reporter writes of it. `section` gets the budget's part of the documents that hold the whole
// report. Returns what the folder's README.md lists (written by write_budget_readme, after the
// figures).
ReportFiles write_budget_tables(const StudyData& study, const std::string& budget, const fs::path& dir,
                                const std::string& heading, const ReportOptions& options,
                                const std::vector<const Reporter*>& reporters, std::ostream& console,
                                BudgetSection& section) {
    make_report_directory(dir);
    const StudyIndex index(study, budget);
    ComparisonOptions comparison;
    comparison.reference = budget_reference(index, options, console);
    comparison.alpha = options.alpha;
    const FactorialFindings factorial = factorial_findings(index, options.alpha, options.rope);
    say_budget_summary(study, budget, index, heading, comparison.reference, factorial, console);
    const std::vector<const SuiteProtocol*> protocols = study_protocols(study, console);
    console << '\n';

    const std::optional<RelativeGaps> gaps = relative_gaps(index);
    // The Bayesian tests: for the table, bayesian_probabilities.csv and the simplex figures' samples.
    const BayesianRope rope{options.rope, options.raw_rope};
    const std::vector<BayesianComparison> bayesian =
        bayesian_comparisons(index, comparison.reference, rope, bayesian_figure_samples);
    write_or_remove(dir / "bayesian_probabilities.csv",
                    bayesian.empty()
                        ? std::nullopt
                        : std::optional<std::string>(bayesian_csv(index, comparison.reference, bayesian)));
    write_or_remove(dir / "bayesian_samples.csv",
                    bayesian.empty() ? std::nullopt
                                     : std::optional<std::string>(bayesian_samples_csv(index, bayesian)));
    const std::vector<Table> tables = budget_tables(
        index, comparison, factorial.designs, factorial.rejected, !study.algorithms.empty(), protocols, gaps,
        precision_rule_of(study.study_text), bayesian, rope, study.wall_seconds);
    const BudgetVerdict verdict = budget_verdict(index, options.alpha, factorial.designs);
    const std::size_t budget_count = study_budgets(study).size();
    const BudgetReportContext context{
        index,       tables, dir, protocols, options.ioh_precision, console, verdict, options.console_tables,
        budget_count};
    for (const Reporter* reporter : reporters)
        reporter->write_tables(context);
    ReportFiles files;
    files.formats.assign(options.formats.begin(), options.formats.end());
    files.bayesian = !bayesian.empty();
    write_curve_data(index, budget, dir, factorial.designs, gaps, options.alpha, files);
    remove_stale_pmsm_tables(dir, tables);
    remove_absent_tables(dir, tables, {"ecdf_area", "ert", "overhead"});
    console << "tables and curve data: " << dir.string() << '\n';
    for (const Reporter* reporter : reporters)
        reporter->write_budget(context);
    files.cec = writes_protocol_files(protocols);
    files.combined = section.folder.empty(); // no folder of its own: this budget is the whole report
    section.budget = budget;
    section.directory = dir;
    section.tables = tables;
    section.verdict = verdict_tables(verdict);
    return files;
}

} // namespace

ReportOutcome build_report(const StudyData& study, const ReportOptions& options, std::ostream& console) {
    check_options(options);
    const fs::path out_dir = options.out_dir.empty() ? study.directory / "report" : options.out_dir;
    make_report_directory(out_dir);
    std::vector<std::string> budgets = study_budgets(study);
    if (budgets.empty())
        throw std::invalid_argument("the study has no runs");
    if (options.reference) { // an error for a reference no budget ran, as before budgets existed
        StudyData all = study;
        for (auto& r : all.runs)
            r.budget.clear();
        (void)resolve_reference(StudyIndex(all), options.reference);
    }

    const std::string heading = "mhbench report of " + study.directory.string() + ": ";
    if (budgets.size() > 1)
        console << heading << budgets.size() << " budgets, each reported in its own folder\n";
    const std::vector<const Reporter*> reporters = selected_reporters(options.formats);
    // Interrupted figures end the figures, not the report: the tables of every budget are still
    // written (they take little time), so that only the figures are left for `mhbench report`.
    bool figures = options.figures;
    std::vector<BudgetSection> sections; // of report.md, report.tex, index.html: one per budget
    if (budgets.size() == 1) {
        const ReportFiles files = write_budget_tables(study, budgets.front(), out_dir, heading, options,
                                                      reporters, console, sections.emplace_back());
        draw_budget_figures(options, out_dir, console, figures, sections.back());
        write_budget_readme(out_dir, sections.back(), files);
    } else {
        // Several budgets: one complete report per budget in <out>/<budget slug>/, the combined
        // report.md / report.tex and budgets.csv (budget,directory) on top. The figures of every
        // budget are drawn by one run of the script (budgets.csv names the folders): Python and
        // matplotlib start once, and the figures of all budgets share the workers.
        std::string index_csv = "budget,directory\n";
        std::vector<ReportFiles> files;
        for (const auto& budget : budgets) {
            const std::string slug = budget_slug(budget);
            index_csv += csv_field(budget) + ',' + csv_field(slug) + '\n';
            sections.emplace_back().folder = slug;
            files.push_back(write_budget_tables(study, budget, out_dir / slug, "budget " + budget + ": ",
                                                options, reporters, console, sections.back()));
        }
        write_file_atomically(out_dir / "budgets.csv", index_csv);
        write_file_atomically(out_dir / "README.md", budgets_readme(budgets, folders_of(sections)));
        draw_budget_figures(options, out_dir, console, figures, sections.front());
        for (std::size_t b = 0; b < sections.size(); ++b) {
            sections[b].figures_current = sections.front().figures_current;
            sections[b].figures_note = sections.front().figures_note;
            write_budget_readme(out_dir / sections[b].folder, sections[b], files[b]);
        }
    }
    ReportOutcome outcome;
    const StudyReportContext context{study, out_dir, sections, console};
    for (const Reporter* reporter : reporters)
        if (const std::optional<fs::path> page = reporter->write_study(context); page && outcome.html.empty())
            outcome.html = *page;
    outcome.interrupted = options.figures && !figures;
    if (outcome.interrupted) {
        std::string again = "mhbench report " + shell_quote(study.directory.string());
        if (!options.out_dir.empty())
            again += " --out " + shell_quote(options.out_dir.string());
        *options.errors << "figures interrupted; run `" << again << "` to draw them\n";
    }
    return outcome;
}

} // namespace mhb
