// The "summary" table: per problem x algorithm the descriptive statistics of the final values, the
// evaluations spent, the error to the optimum, success rate and ERT, and the median best-so-far
// values at fractions of one evaluation count per problem.
#include <cmath>
#include <cstdint>
#include <map>

#include "results/analysis/budget_target.hpp"
#include "results/analysis/evaluation_counts.hpp"
#include "results/analysis/statistics.hpp"
#include "results/tables/comparison_common.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb::tables {

namespace {

// The columns before the budget columns; the rows fill some of them by position.
const std::vector<std::string> statistics_columns = {
    "Problem", "Algorithm", "Runs",  "Evaluations (mean)", "Mean",         "Std", "Median",
    "IQR",     "Best",      "Worst", "Mean error f - f*",  "Success rate", "ERT"};
constexpr std::size_t runs_column = 2;
constexpr std::size_t mean_column = 4;
constexpr std::size_t success_column = 11;
constexpr std::size_t ert_column = 12;
constexpr std::size_t first_budget_column = 13;

// One evaluation count E per problem for the budget columns; when every problem has the same, the
// headers name the counts, else a column gives each problem's E.
struct Budgets {
    std::map<std::string, std::int64_t> per_problem;
    bool one = true; // every problem has the same E

    // The headers can name the counts: one E, and at least one problem to have it.
    [[nodiscard]] bool named() const { return one && !per_problem.empty(); }
    // The first problem's E: every problem's when `one`.
    [[nodiscard]] std::int64_t common() const { return per_problem.begin()->second; }
};

Budgets budgets_of(const StudyIndex& index) {
    Budgets budgets;
    for (const auto& p : index.problems())
        budgets.per_problem[p] = budget_evaluations(index, p);
    for (const auto& [p, e] : budgets.per_problem)
        budgets.one = budgets.one && e == budgets.common();
    return budgets;
}

std::string percent_text(double fraction) {
    return format_number(100.0 * fraction, 3) + "%";
}

void add_budget_headers(Table& t, const ComparisonOptions& options, const Budgets& budgets) {
    for (double fraction : options.budget_fractions)
        t.header.push_back(budgets.named()
                               ? "Median at " + std::to_string(evaluations_at(fraction, budgets.common())) +
                                     " evals (" + percent_text(fraction) + ")"
                               : "Median at " + percent_text(fraction) + " of E");
    if (!budgets.one)
        t.header.push_back("E (evaluations)");
}

// A problem on which no run of any algorithm records reaching a target had none set.
bool problem_has_target(const StudyIndex& index, const std::string& problem) {
    for (const auto& a : index.algorithms_on(problem))
        for (const auto* r : index.find(problem, a)->runs)
            if (r->evaluations_to_target.has_value())
                return true;
    return false;
}

// A group whose every run failed: a row that says so (success rate 0, ERT inf).
std::vector<TableCell> failed_group_row(const StudyIndex& index, const RunGroup& g, std::size_t width,
                                        bool has_target, const Budgets& budgets) {
    std::vector<TableCell> row(width, empty_cell());
    row[0] = text_cell(g.problem);
    row[1] = text_cell(index.label(g.algorithm));
    row[runs_column] = text_cell(runs_text(g));
    row[mean_column] = text_cell(no_successful_run_text(g));
    if (has_target) {
        row[success_column] = number_cell(0.0, 3);
        row[ert_column] = number_cell(INFINITY, 4);
    }
    if (!budgets.one)
        row.back() = number_cell(static_cast<double>(budgets.per_problem.at(g.problem)), 6);
    return row;
}

// The cells of the statistics columns for a group with successful runs.
std::vector<TableCell> statistics_cells(const StudyIndex& index, const RunGroup& g, bool has_target) {
    const Summary s = summarize(g.final_values());
    const std::vector<double> errors = run_errors(g);
    std::vector<TargetHit> hits;
    for (const auto* r : g.runs)
        hits.push_back(
            {r->evaluations_to_target.has_value(), r->evaluations_to_target.value_or(r->evaluations)});
    // Failed runs count as unsuccessful runs that spent nothing we know of.
    std::size_t successes = 0;
    for (const auto& h : hits)
        successes += h.success ? 1 : 0;
    const double total = static_cast<double>(g.runs.size() + g.failed);
    const auto ert = expected_running_time(hits);
    return {text_cell(g.problem),
            text_cell(index.label(g.algorithm)),
            text_cell(runs_text(g)),
            fixed_cell(mean(run_evaluations(g)), 1),
            number_cell(s.mean, 4),
            number_cell(s.std, 2),
            number_cell(s.median, 4),
            number_cell(s.iqr(), 2),
            number_cell(s.best, 4),
            number_cell(s.worst, 4),
            errors.empty() ? empty_cell() : number_cell(mean(errors), 3),
            has_target ? number_cell(static_cast<double>(successes) / total, 3) : empty_cell(),
            !has_target ? empty_cell() : number_cell(ert ? *ert : INFINITY, 4)};
}

// The median over the runs of the best-so-far value at each fraction of the problem's E.
void add_budget_cells(std::vector<TableCell>& row, const RunGroup& g, const ComparisonOptions& options,
                      std::int64_t budget) {
    for (double fraction : options.budget_fractions) {
        std::vector<double> values;
        for (const auto* r : g.runs)
            if (const double v = value_at_evaluations(*r, evaluations_at(fraction, budget)); !std::isnan(v))
                values.push_back(v);
        row.push_back(values.empty() ? empty_cell() : number_cell(summarize(values).median, 4));
    }
}

// Each problem's E, when they differ: the first twelve, then the column.
std::string budget_note(const Budgets& budgets) {
    if (budgets.one)
        return "";
    std::string note = " E per problem:";
    std::size_t listed = 0;
    for (const auto& [p, e] : budgets.per_problem)
        if (++listed <= 12)
            note += (listed == 1 ? " " : ", ") + std::to_string(e) + " on " + p;
    note += budgets.per_problem.size() > 12 ? ", ... (column E)." : ".";
    return note;
}

std::string summary_caption(const StudyIndex& index, const Budgets& budgets, std::size_t without_success) {
    const auto target = budget_target(index.budget());
    std::string caption =
        "Std is the sample standard deviation (two-pass), IQR = q75 - q25 (linear interpolation, type 7). "
        "Success: the run reached the study's target" +
        (target ? ", " + target->condition() : std::string()) +
        " (blank: no run on the problem reached one, or none was set); ERT = evaluations of all runs (to the "
        "target for successful ones) / successful runs, as COCO defines it. Budget columns: median over runs "
        "of the best-so-far value after that many evaluations, "
        "floor(fraction x E), rounded down, for one evaluation count E per problem, "
        "the same for every algorithm: " +
        std::string(
            index.budget().find("evaluations=") != std::string::npos
                ? "the study's evaluation budget"
                : "the largest evaluation count any run on the problem spent (the budget is not one of "
                  "evaluations)") +
        "; a run that stopped earlier counts with its final value." + budget_note(budgets);
    if (index.failed_runs() > 0)
        caption += " Runs: successful/total; a failed run counts as unsuccessful in the success rate and "
                   "is left out of every other column.";
    if (without_success > 0)
        // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) of " " + std::string inlined here.
        caption.append(" ")
            .append(std::to_string(without_success))
            .append(without_success == 1 ? " group has" : " groups have")
            .append(" no successful run.");
    return caption + left_out_notes(index);
}

// LaTeX: the problem and algorithm repeat in every part; the parts are named by these groups.
void summary_latex_layout(Table& t, const ComparisonOptions& options, const Budgets& budgets) {
    t.latex_column(0).fold_constant = true;
    t.latex_column(0).heading = true; // the problem heads its rows: a column less
    t.latex_column(1).key = true;
    t.latex_column(runs_column).fold_constant = true; // "20/20" on every row, typically
    const auto group = [&](std::size_t from, std::size_t to, const char* name) {
        for (std::size_t c = from; c < to && c < t.header.size(); ++c)
            t.latex_column(c).group = name;
    };
    group(2, 4, "runs");
    group(4, 8, "location and spread");
    group(8, 11, "range");
    group(11, 13, "target");
    group(first_budget_column, t.header.size(), "budget");
    set_latex_headers(
        t, {{3, "Evals.\\\\(mean)"}, {10, "Mean error\\\\$f - f^*$"}, {success_column, "Success\\\\rate"}});
    for (std::size_t k = 0; k < options.budget_fractions.size(); ++k) {
        const double fraction = options.budget_fractions[k];
        t.latex_column(first_budget_column + k).header =
            budgets.named() ? "Median at\\\\" + std::to_string(evaluations_at(fraction, budgets.common())) +
                                  " evals\\\\(" + format_number(100.0 * fraction, 3) + "\\%)"
                            : "Median at\\\\" + format_number(100.0 * fraction, 3) + "\\% of $E$";
    }
    if (!budgets.one)
        t.latex_column(t.header.size() - 1).header = "$E$\\\\(evals)";
}

} // namespace

Table summary_table(const StudyIndex& index, const ComparisonOptions& options) {
    Table t;
    t.id = "summary";
    t.title = "Summary of final best-so-far values per problem and algorithm";
    t.header = statistics_columns;
    const Budgets budgets = budgets_of(index);
    add_budget_headers(t, options, budgets);
    std::size_t without_success = 0;
    for (const auto& g : index.groups()) {
        const bool has_target = problem_has_target(index, g.problem);
        if (g.runs.empty()) {
            ++without_success;
            t.add_row(failed_group_row(index, g, t.header.size(), has_target, budgets));
            continue;
        }
        std::vector<TableCell> row = statistics_cells(index, g, has_target);
        const std::int64_t budget = budgets.per_problem.at(g.problem);
        add_budget_cells(row, g, options, budget);
        if (!budgets.one)
            row.push_back(number_cell(static_cast<double>(budget), 6));
        t.add_row(std::move(row));
    }
    t.caption = summary_caption(index, budgets, without_success);
    t.latex_note = "Final best-so-far value over the runs; Success and ERT to the study's target; budget "
                   "columns: median after that share of the evaluations (Methods)." +
                   left_out_notes(index);
    t.methods = {t.caption.substr(0, t.caption.size() - left_out_notes(index).size())};
    summary_latex_layout(t, options, budgets);
    format_columns(t);
    return t;
}

} // namespace mhb::tables
