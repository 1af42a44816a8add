#include "results/tables/comparison_tables.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "results/analysis/evaluation_counts.hpp"
#include "results/analysis/hypothesis_tests.hpp"
#include "results/analysis/statistics.hpp"

namespace mhb {

namespace {

TableCell empty_cell() {
    return text_cell("");
}

std::string alpha_text(double alpha) {
    return format_number(alpha, 3);
}

} // namespace

std::string win_tie_loss(const std::vector<std::string>& markers) {
    std::size_t w = 0;
    std::size_t t = 0;
    std::size_t l = 0;
    for (const auto& m : markers) {
        w += m == "+" ? 1U : 0U;
        t += m == "=" ? 1U : 0U;
        l += m == "-" ? 1U : 0U;
    }
    return std::to_string(w) + "/" + std::to_string(t) + "/" + std::to_string(l);
}

TableCell marker_cell(const std::string& marker) {
    TableCell cell = text_cell(marker);
    if (!marker.empty())
        cell.latex = "$" + marker + "$";
    return cell;
}

namespace {

// A test's name as a cell; LaTeX says only its variant (the caption names the test): "exact" or
// "normal approx." (with tie and continuity correction).
TableCell test_cell(const TestResult& test) {
    TableCell cell = text_cell(test.name);
    const std::size_t comma = test.name.find(", ");
    const std::string variant = comma == std::string::npos ? "" : test.name.substr(comma + 2);
    cell.latex =
        variant.empty() ? "---" : (variant.rfind("normal approx.", 0) == 0 ? "normal approx." : variant);
    return cell;
}

const char* const wtl_note =
    " Rows under the rule: w/t/l, the number of problems on which the algorithm is significantly better "
    "than the reference (+), not significantly different (=) and significantly worse (-).";

// What a group without a successful run shows where its statistics would be.
std::string no_successful_run_text(const RunGroup& g) {
    return "no successful run (" + std::to_string(g.failed) + " failed)";
}

std::string percent_text(double fraction) {
    return format_number(100.0 * fraction, 3) + "%";
}

// Every value of x and y is the same one (+inf included).
bool all_equal(const std::vector<double>& x, const std::vector<double>& y) {
    const double first = x.empty() ? (y.empty() ? 0.0 : y.front()) : x.front();
    const auto same = [first](double v) { return v == first; };
    return std::all_of(x.begin(), x.end(), same) && std::all_of(y.begin(), y.end(), same);
}

struct Comparison {
    std::string problem;
    std::string algorithm;
    TestResult test; // rank-sum, always
    double adjusted_p = 1.0;
    double a12 = 0.5;
    bool paired = false; // the problem's runs are paired by seed: the signed-rank test decides
    std::size_t pairs = 0;
    TestResult paired_test; // signed-rank on the paired differences (algorithm - reference)
    double paired_adjusted_p = 1.0;
    std::string marker;
    // Degenerate tests, which the tables report by convention (z = 0, p = 1, '=') where R's
    // wilcox.test gives NaN: every value of both samples equal; every paired difference zero.
    bool every_value_tied = false;
    bool every_difference_zero = false;
};

std::vector<Comparison> compare_with_reference(const StudyIndex& index, const ComparisonOptions& options) {
    std::vector<Comparison> all;
    for (const auto& p : index.problems()) {
        const RunGroup* reference = index.find(p, options.reference);
        if (reference == nullptr)
            continue;
        const bool paired = index.paired(p);
        std::vector<Comparison> family;
        std::vector<std::size_t> nonzero;
        for (const auto& a : index.algorithms_on(p)) {
            if (a == options.reference)
                continue;
            const RunGroup& group = *index.find(p, a);
            const auto x = group.final_values();
            const auto y = reference->final_values();
            Comparison c{p,      a, rank_sum_test(x, y), 1.0, vargha_delaney_a12(x, y),
                         paired, 0, TestResult{},        1.0, ""};
            c.every_value_tied = all_equal(x, y);
            std::size_t differing = 0;
            if (paired) {
                const PairedValues pairs = paired_final_values(group, *reference);
                c.pairs = pairs.x.size();
                c.paired_test = signed_rank_test(pairs.x, pairs.y);
                for (std::size_t i = 0; i < pairs.x.size(); ++i)
                    differing += pairs.x[i] != pairs.y[i] ? 1U : 0U;
            }
            c.every_difference_zero = paired && differing == 0;
            family.push_back(std::move(c));
            nonzero.push_back(differing);
        }
        std::vector<double> raw;
        std::vector<double> paired_raw;
        for (const auto& c : family) {
            raw.push_back(c.test.p_value);
            paired_raw.push_back(c.paired_test.p_value);
        }
        const auto adjusted = holm_adjust(raw);
        const auto paired_adjusted = holm_adjust(paired_raw);
        for (std::size_t i = 0; i < family.size(); ++i) {
            family[i].adjusted_p = adjusted[i];
            family[i].paired_adjusted_p = paired_adjusted[i];
            family[i].marker = paired ? signed_rank_marker(paired_adjusted[i], family[i].paired_test,
                                                           nonzero[i], options.alpha)
                                      : comparison_marker(adjusted[i], family[i].a12, options.alpha);
            all.push_back(family[i]);
        }
    }
    return all;
}

// What a caption naming the tests must add when some were degenerate (empty when none was).
std::string degenerate_tests_note(const std::vector<Comparison>& comparisons) {
    std::size_t tied = 0;
    std::size_t zero = 0;
    for (const auto& c : comparisons) {
        tied += c.every_value_tied ? 1U : 0U;
        zero += c.every_difference_zero ? 1U : 0U;
    }
    std::string note;
    if (tied > 0)
        note += " In " + std::to_string(tied) + (tied == 1 ? " comparison" : " comparisons") +
                " every value of both samples is the same: the rank-sum test has no variance there (R's "
                "wilcox.test gives p = NaN); shown as z = 0, p = 1, =.";
    if (zero > 0)
        note += " In " + std::to_string(zero) + (zero == 1 ? " comparison" : " comparisons") +
                " every paired difference is zero: the signed-rank test has nothing to rank (R gives V = 0, "
                "p = NaN); shown as V = 0, p = 1, =.";
    return note;
}

Table summary_table(const StudyIndex& index, const ComparisonOptions& options) {
    Table t;
    t.id = "summary";
    t.title = "Summary of final best-so-far values per problem and algorithm";
    t.header = {"Problem", "Algorithm", "Runs",  "Evaluations (mean)", "Mean",         "Std", "Median",
                "IQR",     "Best",      "Worst", "Mean error f - f*",  "Success rate", "ERT"};
    // One evaluation count E per problem for the budget columns; when every problem has the same,
    // the headers name the counts, else a column gives each problem's E.
    std::map<std::string, std::int64_t> budgets;
    for (const auto& p : index.problems())
        budgets[p] = budget_evaluations(index, p);
    bool one_budget = true;
    for (const auto& [p, e] : budgets)
        one_budget = one_budget && e == budgets.begin()->second;
    const std::size_t first_budget_column = t.header.size();
    for (double fraction : options.budget_fractions)
        t.header.push_back(one_budget && !budgets.empty()
                               ? "Median at " +
                                     std::to_string(evaluations_at(fraction, budgets.begin()->second)) +
                                     " evals (" + percent_text(fraction) + ")"
                               : "Median at " + percent_text(fraction) + " of E");
    if (!one_budget)
        t.header.push_back("E (evaluations)");
    // A problem on which no run of any algorithm records reaching a target had none set.
    const auto problem_has_target = [&](const std::string& problem) {
        for (const auto& a : index.algorithms_on(problem))
            for (const auto* r : index.find(problem, a)->runs)
                if (r->evaluations_to_target.has_value())
                    return true;
        return false;
    };
    std::size_t without_success = 0;
    for (const auto& g : index.groups()) {
        const bool has_target = problem_has_target(g.problem);
        const std::int64_t budget = budgets[g.problem];
        if (g.runs.empty()) { // every run failed: a row that says so (success rate 0, ERT inf)
            ++without_success;
            std::vector<TableCell> row(t.header.size(), empty_cell());
            row[0] = text_cell(g.problem);
            row[1] = text_cell(index.label(g.algorithm));
            row[2] = text_cell("0/" + std::to_string(g.failed));
            row[4] = text_cell(no_successful_run_text(g));
            if (has_target) {
                row[11] = number_cell(0.0, 3);
                row[12] = number_cell(INFINITY, 4);
            }
            if (!one_budget)
                row.back() = number_cell(static_cast<double>(budget), 6);
            t.add_row(std::move(row));
            continue;
        }
        const Summary s = summarize(g.final_values());
        std::vector<double> evaluations;
        std::vector<double> errors;
        std::vector<TargetHit> hits;
        for (const auto* r : g.runs) {
            evaluations.push_back(static_cast<double>(r->evaluations));
            if (r->error())
                errors.push_back(*r->error());
            hits.push_back(
                {r->evaluations_to_target.has_value(), r->evaluations_to_target.value_or(r->evaluations)});
        }
        // Failed runs count as unsuccessful runs that spent nothing we know of.
        std::size_t successes = 0;
        for (const auto& h : hits)
            successes += h.success ? 1 : 0;
        const double total = static_cast<double>(g.runs.size() + g.failed);
        const auto ert = expected_running_time(hits);
        std::vector<TableCell> row = {
            text_cell(g.problem),
            text_cell(index.label(g.algorithm)),
            text_cell(std::to_string(g.runs.size()) + "/" + std::to_string(g.runs.size() + g.failed)),
            fixed_cell(mean(evaluations), 1),
            number_cell(s.mean, 4),
            number_cell(s.std, 2),
            number_cell(s.median, 4),
            number_cell(s.iqr(), 2),
            number_cell(s.best, 4),
            number_cell(s.worst, 4),
            errors.empty() ? empty_cell() : number_cell(mean(errors), 3),
            has_target ? number_cell(static_cast<double>(successes) / total, 3) : empty_cell(),
            !has_target ? empty_cell() : number_cell(ert ? *ert : INFINITY, 4)};
        for (double fraction : options.budget_fractions) {
            std::vector<double> values;
            for (const auto* r : g.runs)
                if (const double v = value_at_evaluations(*r, evaluations_at(fraction, budget));
                    !std::isnan(v))
                    values.push_back(v);
            row.push_back(values.empty() ? empty_cell() : number_cell(summarize(values).median, 4));
        }
        if (!one_budget)
            row.push_back(number_cell(static_cast<double>(budget), 6));
        t.add_row(std::move(row));
    }
    std::string budget_note;
    if (!one_budget) {
        budget_note = " E per problem:";
        std::size_t listed = 0;
        for (const auto& [p, e] : budgets)
            if (++listed <= 12)
                budget_note += (listed == 1 ? " " : ", ") + std::to_string(e) + " on " + p;
        budget_note += budgets.size() > 12 ? ", ... (column E)." : ".";
    }
    t.caption =
        "Std is the sample standard deviation (two-pass), IQR = q75 - q25 (linear interpolation, type 7). "
        "Success: the run reached the study's target (blank: no run on the problem reached one, or none was "
        "set); ERT = evaluations of all runs (to the target for successful ones) / successful runs, as COCO "
        "defines it. Budget columns: median over runs of the best-so-far value after that many evaluations, "
        "floor(fraction x E), rounded down, for one evaluation count E per problem, "
        "the same for every algorithm: " +
        std::string(
            index.budget().find("evaluations=") != std::string::npos
                ? "the study's evaluation budget"
                : "the largest evaluation count any run on the problem spent (the budget is not one of "
                  "evaluations)") +
        "; a run that stopped earlier counts with its final value." + budget_note;
    if (index.failed_runs() > 0)
        t.caption += " Runs: successful/total; a failed run counts as unsuccessful in the success rate and "
                     "is left out of every other column.";
    if (without_success > 0)
        t.caption += " " + std::to_string(without_success) +
                     (without_success == 1 ? " group has" : " groups have") + " no successful run.";
    t.caption += left_out_notes(index);

    // LaTeX: the problem and algorithm repeat in every part; the parts are named by these groups.
    t.latex_column(0).fold_constant = true;
    t.latex_column(0).heading = true; // the problem heads its rows: a column less
    t.latex_column(1).key = true;
    t.latex_column(2).fold_constant = true; // "20/20" on every row, typically
    const auto group = [&](std::size_t from, std::size_t to, const char* name) {
        for (std::size_t c = from; c < to && c < t.header.size(); ++c)
            t.latex_column(c).group = name;
    };
    group(2, 4, "runs");
    group(4, 8, "location and spread");
    group(8, 11, "range");
    group(11, 13, "target");
    group(first_budget_column, t.header.size(), "budget");
    t.latex_column(3).header = "Evals.\\\\(mean)";
    t.latex_column(10).header = "Mean error\\\\$f - f^*$";
    t.latex_column(11).header = "Success\\\\rate";
    for (std::size_t k = 0; k < options.budget_fractions.size(); ++k) {
        const double fraction = options.budget_fractions[k];
        t.latex_column(first_budget_column + k).header =
            one_budget && !budgets.empty()
                ? "Median at\\\\" + std::to_string(evaluations_at(fraction, budgets.begin()->second)) +
                      " evals\\\\(" + format_number(100.0 * fraction, 3) + "\\%)"
                : "Median at\\\\" + format_number(100.0 * fraction, 3) + "\\% of $E$";
    }
    if (!one_budget)
        t.latex_column(t.header.size() - 1).header = "$E$\\\\(evals)";
    format_columns(t);
    return t;
}

Table tests_table(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                  const ComparisonOptions& options) {
    Table t;
    t.id = "tests";
    t.title = "Tests against the reference " + index.label(options.reference);
    t.header = {"Problem",
                "Algorithm",
                "Rank-sum test",
                "W",
                "z",
                "p",
                "p (Holm)",
                "A12",
                "Paired runs",
                "Signed-rank test",
                "V",
                "Signed-rank z",
                "Signed-rank p",
                "Signed-rank p (Holm)",
                "Result",
                "Result by"};
    bool any_paired = false;
    bool any_unpaired = false;
    for (const auto& c : comparisons) {
        any_paired = any_paired || c.paired;
        any_unpaired = any_unpaired || !c.paired;
        std::vector<TableCell> row = {text_cell(c.problem),
                                      text_cell(index.label(c.algorithm)),
                                      test_cell(c.test),
                                      number_cell(c.test.statistic, 6),
                                      c.test.exact ? empty_cell() : number_cell(c.test.z, 3),
                                      number_cell(c.test.p_value, 3),
                                      number_cell(c.adjusted_p, 3),
                                      number_cell(c.a12, 3)};
        if (c.paired) {
            row.push_back(number_cell(static_cast<double>(c.pairs), 6));
            row.push_back(test_cell(c.paired_test));
            row.push_back(number_cell(c.paired_test.statistic, 6));
            row.push_back(c.paired_test.exact ? empty_cell() : number_cell(c.paired_test.z, 3));
            row.push_back(number_cell(c.paired_test.p_value, 3));
            row.push_back(number_cell(c.paired_adjusted_p, 3));
        } else {
            row.push_back(text_cell("no (seeds differ)"));
            for (int i = 0; i < 5; ++i)
                row.push_back(empty_cell());
        }
        row.push_back(marker_cell(c.marker));
        row.push_back(text_cell(c.paired ? "signed-rank" : "rank-sum"));
        t.add_row(std::move(row));
    }
    // Under the rule, each algorithm's wins, ties and losses over the problems.
    for (const auto& a : index.algorithms()) {
        std::vector<std::string> markers;
        for (const auto& c : comparisons)
            if (c.algorithm == a)
                markers.push_back(c.marker);
        if (markers.empty())
            continue;
        std::vector<TableCell> row(t.header.size(), empty_cell());
        row[0] = text_cell("w/t/l");
        row[1] = text_cell(index.label(a));
        row[14] = text_cell(win_tie_loss(markers));
        t.add_footer(std::move(row));
    }
    std::vector<std::string> untested;
    for (const auto& p : index.problems()) {
        const RunGroup* reference = index.group(p, options.reference);
        if (index.find(p, options.reference) != nullptr || reference == nullptr)
            continue;
        untested.push_back(p);
    }
    std::string caption =
        "Two-sided Wilcoxon rank-sum test (Mann-Whitney U; W = U of the algorithm) of each algorithm's "
        "final values against the reference's, Holm-adjusted across the comparisons of each problem; A12 = "
        "Vargha-Delaney effect size P(algorithm > reference) + P(=)/2 (below 0.5: the algorithm tends to "
        "lower, better values).";
    if (any_paired)
        caption +=
            " Where the runs are paired (every algorithm's run r on the problem has the same seed: common "
            "random numbers), also the two-sided Wilcoxon signed-rank test of the paired differences "
            "algorithm - reference over the run indices both completed (V = sum of the ranks of positive "
            "differences; zero differences dropped, as R's wilcox.test(paired = TRUE)), Holm-adjusted across "
            "the comparisons of each problem.";
    caption += std::string(" Result (alpha = ") + alpha_text(options.alpha) +
               ") from the test named in \"Result by\": " +
               (any_paired && any_unpaired ? "the signed-rank test where runs are paired, the rank-sum test "
                                             "where they are not"
                                           : (any_paired ? "the signed-rank test (all runs paired)"
                                                         : "the rank-sum test (no runs paired)")) +
               ". +: significantly better than the reference, -: significantly worse, =: no significant "
               "difference. Test variants: exact = the exact null distribution, normal approx. = the normal "
               "approximation with tie and continuity correction." +
               degenerate_tests_note(comparisons) + wtl_note;
    if (!untested.empty()) {
        caption += " Not tested (every run of the reference failed):";
        for (std::size_t i = 0; i < untested.size(); ++i)
            caption += (i == 0 ? " " : ", ") + untested[i];
        caption += ".";
    }
    caption += left_out_notes(index);
    t.caption = std::move(caption);

    // LaTeX: a rank-sum part and a signed-rank part when both do not fit; the name of a test is
    // said once in the notes when every row has the same.
    t.latex_column(0).fold_constant = true;
    t.latex_column(0).heading = true;
    t.latex_column(1).key = true;
    for (std::size_t c = 2; c <= 7; ++c)
        t.latex_column(c).group = "rank-sum test";
    for (std::size_t c = 8; c <= 13; ++c)
        t.latex_column(c).group = "signed-rank test";
    t.latex_column(14).group = "result";
    t.latex_column(15).group = "result";
    for (const std::size_t c : {std::size_t{2}, std::size_t{9}, std::size_t{15}})
        t.latex_column(c).fold_constant = true;
    t.latex_column(2).header = "Rank-sum\\\\test";
    t.latex_column(9).header = "Signed-rank\\\\test";
    t.latex_column(5).header = "$p$";
    t.latex_column(6).header = "$p$\\\\(Holm)";
    t.latex_column(8).header = "Paired\\\\runs";
    t.latex_column(11).header = "Signed-\\\\rank $z$";
    t.latex_column(12).header = "Signed-\\\\rank $p$";
    t.latex_column(13).header = "Signed-\\\\rank $p$\\\\(Holm)";
    format_columns(t);
    return t;
}

Table generic_table(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                    const ComparisonOptions& options) {
    Table t;
    t.id = "comparison";
    t.title = "Final values: median (IQR) per problem and algorithm";
    t.header = {"Problem"};
    for (const auto& a : index.algorithms())
        t.header.push_back(a == options.reference ? index.label(a) + " (reference)" : index.label(a));
    t.header.push_back("Markers by");
    std::size_t least_runs = SIZE_MAX;
    bool any_paired = false;
    bool any_unpaired = false;
    std::size_t most_runs = 0;
    // Each algorithm's markers over the problems, for the w/t/l row.
    std::vector<std::vector<std::string>> markers(index.algorithms().size());
    for (const auto& p : index.problems()) {
        std::vector<TableCell> row = {text_cell(p)};
        // The markers come from rank tests of the final values, so the cell shows what they test:
        // the median and the IQR (a mean can sit on the other side of the reference's than most runs).
        double best = INFINITY;
        for (const auto& a : index.algorithms())
            if (const auto* g = index.find(p, a))
                best = std::min(best, summarize(g->final_values()).median);
        for (std::size_t j = 0; j < index.algorithms().size(); ++j) {
            const std::string& a = index.algorithms()[j];
            const auto* g = index.find(p, a);
            if (g == nullptr) {
                const RunGroup* failed = index.group(p, a);
                TableCell cell =
                    failed == nullptr ? empty_cell() : text_cell(no_successful_run_text(*failed));
                if (failed != nullptr)
                    cell.latex = "all " + std::to_string(failed->failed) + " failed";
                row.push_back(std::move(cell));
                continue;
            }
            least_runs = std::min(least_runs, g->runs.size());
            most_runs = std::max(most_runs, g->runs.size());
            const Summary s = summarize(g->final_values());
            std::string marker;
            for (const auto& c : comparisons)
                if (c.problem == p && c.algorithm == a) {
                    marker = c.marker;
                    markers[j].push_back(c.marker);
                }
            TableCell cell = spread_cell(s.median, s.iqr(), marker, {3, -1}, {2, -1});
            // No bold when the best median is infinite: nothing is best where every median is inf.
            cell.bold = std::isfinite(best) && s.median == best;
            row.push_back(std::move(cell));
        }
        const bool compared = std::any_of(comparisons.begin(), comparisons.end(),
                                          [&](const Comparison& c) { return c.problem == p; });
        const bool paired = index.paired(p);
        any_paired = any_paired || (compared && paired);
        any_unpaired = any_unpaired || (compared && !paired);
        row.push_back(text_cell(!compared ? "" : (paired ? "signed-rank (paired)" : "rank-sum")));
        t.add_row(std::move(row));
    }
    if (!comparisons.empty()) {
        std::vector<TableCell> row(t.header.size(), empty_cell());
        row[0] = text_cell("w/t/l");
        for (std::size_t j = 0; j < markers.size(); ++j)
            if (index.algorithms()[j] != options.reference)
                row[j + 1] = text_cell(win_tie_loss(markers[j]));
        t.add_footer(std::move(row));
    }
    const std::string runs = least_runs == most_runs || least_runs == SIZE_MAX
                                 ? std::to_string(most_runs)
                                 : std::to_string(least_runs) + "-" + std::to_string(most_runs);
    std::string tests;
    if (any_paired)
        tests = "two-sided Wilcoxon signed-rank test of the paired differences (runs paired by seed: common "
                "random numbers)";
    if (any_paired && any_unpaired)
        tests += " on the problems marked so, ";
    if (any_unpaired)
        tests += "two-sided Wilcoxon rank-sum test (Mann-Whitney U)";
    if (any_paired && any_unpaired)
        tests += " on the others (seeds differ)";
    if (tests.empty())
        tests = "none (no problem has runs of the reference and another algorithm)";
    t.caption = "Median (IQR = q75 - q25) of the final best-so-far value over " + runs +
                " runs; lowest median in bold. The median is shown because the markers come from rank tests "
                "of the final values, which compare where the runs lie, not their mean. Markers against the "
                "reference " +
                index.label(options.reference) + ": " + tests +
                ", Holm correction across each problem's comparisons, alpha = " + alpha_text(options.alpha) +
                "; + better, - worse, = no significant difference." + degenerate_tests_note(comparisons) +
                (comparisons.empty() ? "" : wtl_note) + left_out_notes(index);
    // LaTeX: the IQR under the median keeps the columns narrow; the test is said once when it is the
    // same for every problem.
    t.latex_spread_below = true;
    t.latex_column(0).fold_constant = true;
    t.latex_column(0).wrap = true; // specs break after ',' and ':'; more algorithms fit beside them
    t.latex_column(t.header.size() - 1).fold_constant = true;
    format_columns(t);
    return t;
}

std::optional<Table> across_problems_table(const StudyIndex& index, const ComparisonOptions& options) {
    const auto medians_or_none = per_problem_medians(index);
    if (!medians_or_none)
        return std::nullopt;
    const auto& [problems, medians] = *medians_or_none;
    const auto& algorithms = index.algorithms();
    const FriedmanResult friedman = friedman_test(medians);
    const std::size_t control = static_cast<std::size_t>(
        std::find(algorithms.begin(), algorithms.end(), options.reference) - algorithms.begin());
    std::vector<double> posthoc = friedman_posthoc_p_values(friedman.average_ranks, problems.size(), control);
    std::vector<double> posthoc_raw;
    std::vector<double> signed_raw;
    std::vector<TestResult> signed_tests(algorithms.size());
    for (std::size_t j = 0; j < algorithms.size(); ++j) {
        if (j == control)
            continue;
        std::vector<double> x;
        std::vector<double> y;
        for (const auto& row : medians) {
            x.push_back(row[j]);
            y.push_back(row[control]);
        }
        signed_tests[j] = signed_rank_test(x, y);
        posthoc_raw.push_back(posthoc[j]);
        signed_raw.push_back(signed_tests[j].p_value);
    }
    const auto posthoc_adjusted = holm_adjust(posthoc_raw);
    const auto signed_adjusted = holm_adjust(signed_raw);
    Table t;
    t.id = "across_problems";
    t.title = "Across problems: Friedman average ranks and Wilcoxon signed-rank against " +
              index.label(options.reference);
    t.header = {"Algorithm",     "Average rank",         "Post-hoc p (Holm)", "Signed-rank V",
                "Signed-rank p", "Signed-rank p (Holm)", "Signed-rank test"};
    double best_rank = INFINITY;
    for (double r : friedman.average_ranks)
        best_rank = std::min(best_rank, r);
    std::size_t i = 0;
    for (std::size_t j = 0; j < algorithms.size(); ++j) {
        TableCell rank = number_cell(friedman.average_ranks[j], 4);
        rank.bold = friedman.average_ranks[j] == best_rank;
        if (j == control) {
            t.add_row({text_cell(index.label(algorithms[j]) + " (reference)"), rank, empty_cell(),
                       empty_cell(), empty_cell(), empty_cell(), empty_cell()});
            continue;
        }
        t.add_row({text_cell(index.label(algorithms[j])), rank, number_cell(posthoc_adjusted[i], 3),
                   number_cell(signed_tests[j].statistic, 6), number_cell(signed_tests[j].p_value, 3),
                   number_cell(signed_adjusted[i], 3), test_cell(signed_tests[j])});
        ++i;
    }
    t.latex_column(2).header = "Post-hoc $p$\\\\(Holm)";
    t.latex_column(3).header = "Signed-\\\\rank $V$";
    t.latex_column(4).header = "Signed-\\\\rank $p$";
    t.latex_column(5).header = "Signed-\\\\rank $p$\\\\(Holm)";
    t.latex_column(6).fold_constant = true;
    t.latex_column(6).header = "Signed-rank\\\\test";
    const std::size_t left_out = index.problems().size() - problems.size();
    t.caption =
        "Over " + std::to_string(problems.size()) +
        " problems (per-problem medians of the final values; rank 1 = "
        "lowest" +
        (left_out == 0 ? std::string()
                       : "; " + std::to_string(left_out) + (left_out == 1 ? " problem" : " problems") +
                             " left out, on which some algorithm has no successful run") +
        "). Friedman test: chi-square = " + format_number(friedman.chi_square, 5) +
        ", df = " + format_number(friedman.degrees_of_freedom) +
        ", p = " + format_number(friedman.p_value, 3) +
        ". Post-hoc: z = (R_j - R_ref) / sqrt(k(k+1)/(6N)) against the reference, Holm-adjusted. Wilcoxon "
        "signed-rank test of each algorithm's per-problem medians against the reference's, paired by "
        "problem, Holm-adjusted; alpha = " +
        alpha_text(options.alpha) + "." + left_out_notes(index);
    format_columns(t);
    return t;
}

} // namespace

std::string resolve_reference(const StudyIndex& index, const std::optional<std::string>& requested) {
    const auto& algorithms = index.algorithms();
    if (algorithms.empty())
        throw std::invalid_argument("the study has no runs");
    std::string known;
    for (const auto& a : algorithms)
        known += (known.empty() ? "" : ", ") + a + (index.label(a) == a ? "" : " (" + index.label(a) + ")");
    if (!requested) {
        // The paper's ITLBO (all defaults) if the study has it, else its first ITLBO variant.
        for (const auto& a : algorithms)
            if (a == "itlbo")
                return a;
        for (const auto& a : algorithms)
            if (split_spec_text(a).name == "itlbo")
                return a;
        return algorithms.front();
    }
    for (const auto& a : algorithms)
        if (a == *requested)
            return a;
    std::vector<std::string> matches;
    for (const auto& a : algorithms)
        if (index.label(a) == *requested)
            matches.push_back(a);
    if (matches.empty())
        for (const auto& a : algorithms)
            if (split_spec_text(a).name == *requested)
                matches.push_back(a);
    if (matches.size() == 1)
        return matches.front();
    throw std::invalid_argument("--reference '" + *requested + "' " +
                                (matches.empty() ? "is not an algorithm of the study"
                                                 : "names several algorithms; give the full spec") +
                                " (the study has: " + known + ")");
}

std::string comparison_marker(double adjusted_p, double a12, double alpha) {
    if (adjusted_p >= alpha || a12 == 0.5)
        return "=";
    return a12 < 0.5 ? "+" : "-";
}

std::string signed_rank_marker(double adjusted_p, const TestResult& signed_rank, std::size_t nonzero_pairs,
                               double alpha) {
    const double n = static_cast<double>(nonzero_pairs);
    const double centred = signed_rank.statistic - n * (n + 1.0) / 4.0;
    if (adjusted_p >= alpha || centred == 0.0)
        return "=";
    return centred < 0.0 ? "+" : "-";
}

std::vector<Table> comparison_tables(const StudyIndex& index, const ComparisonOptions& options) {
    std::vector<Table> tables;
    tables.push_back(summary_table(index, options));
    const auto comparisons = compare_with_reference(index, options);
    if (!comparisons.empty())
        tables.push_back(tests_table(index, comparisons, options));
    tables.push_back(generic_table(index, comparisons, options));
    if (auto across = across_problems_table(index, options))
        tables.push_back(std::move(*across));
    return tables;
}

} // namespace mhb
