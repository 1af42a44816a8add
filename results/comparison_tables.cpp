#include "results/comparison_tables.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "results/hypothesis_tests.hpp"
#include "results/statistics.hpp"

namespace mhb {

namespace {

TableCell empty_cell() {
    return text_cell("");
}

std::string alpha_text(double alpha) {
    return format_number(alpha, 3);
}

// Best-so-far of a run after at most `budget` evaluations (from its iteration curve and its
// checkpoints, whichever recorded the latest point within the budget); NaN if none is.
double value_at_budget(const RunRecord& r, double budget) {
    std::int64_t best_evaluations = -1;
    double value = NAN;
    const auto consider = [&](std::int64_t evaluations, double f) {
        if (static_cast<double>(evaluations) <= budget && evaluations >= best_evaluations) {
            best_evaluations = evaluations;
            value = f;
        }
    };
    for (const auto& p : r.curve)
        consider(p.evaluations, p.best_f);
    for (const auto& c : r.checkpoints)
        consider(c.evaluations, c.best_f);
    return value;
}

std::string percent_text(double fraction) {
    return format_number(100.0 * fraction, 3) + "%";
}

struct Comparison {
    std::string problem;
    std::string algorithm;
    TestResult test;
    double adjusted_p = 1.0;
    double a12 = 0.5;
    std::string marker;
};

std::vector<Comparison> compare_with_reference(const StudyIndex& index, const ComparisonOptions& options) {
    std::vector<Comparison> all;
    for (const auto& p : index.problems()) {
        const RunGroup* reference = index.find(p, options.reference);
        if (reference == nullptr)
            continue;
        std::vector<Comparison> family;
        for (const auto& a : index.algorithms_on(p)) {
            if (a == options.reference)
                continue;
            const auto x = index.find(p, a)->final_values();
            const auto y = reference->final_values();
            family.push_back({p, a, rank_sum_test(x, y), 1.0, vargha_delaney_a12(x, y), ""});
        }
        std::vector<double> raw;
        for (const auto& c : family)
            raw.push_back(c.test.p_value);
        const auto adjusted = holm_adjust(raw);
        for (std::size_t i = 0; i < family.size(); ++i) {
            family[i].adjusted_p = adjusted[i];
            family[i].marker = comparison_marker(adjusted[i], family[i].a12, options.alpha);
            all.push_back(family[i]);
        }
    }
    return all;
}

Table summary_table(const StudyIndex& index, const ComparisonOptions& options) {
    Table t;
    t.id = "summary";
    t.title = "Summary of final best-so-far values per problem and algorithm";
    t.header = {"Problem", "Algorithm", "Runs",  "Evaluations (mean)", "Mean",         "Std", "Median",
                "IQR",     "Best",      "Worst", "Mean error f - f*",  "Success rate", "ERT"};
    for (double fraction : options.budget_fractions)
        t.header.push_back("Median at " + percent_text(fraction) + " budget");
    for (const auto& g : index.groups()) {
        if (g.runs.empty()) {
            std::vector<TableCell> row(t.header.size(), empty_cell());
            row[0] = text_cell(g.problem);
            row[1] = text_cell(g.algorithm);
            row[2] = text_cell("0/" + std::to_string(g.failed));
            t.add_row(std::move(row));
            continue;
        }
        const Summary s = summarize(g.final_values());
        std::vector<double> evaluations;
        std::vector<double> errors;
        std::vector<TargetHit> hits;
        double most_evaluations = 0.0;
        for (const auto* r : g.runs) {
            evaluations.push_back(static_cast<double>(r->evaluations));
            most_evaluations = std::max(most_evaluations, static_cast<double>(r->evaluations));
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
        // A problem on which no run of any algorithm records reaching a target had none set.
        bool has_target = false;
        for (const auto& a : index.algorithms_on(g.problem))
            for (const auto* r : index.find(g.problem, a)->runs)
                has_target = has_target || r->evaluations_to_target.has_value();
        std::vector<TableCell> row = {
            text_cell(g.problem),
            text_cell(g.algorithm),
            text_cell(std::to_string(g.runs.size()) + "/" + std::to_string(g.runs.size() + g.failed)),
            number_cell(mean(evaluations), 6),
            number_cell(s.mean),
            number_cell(s.std, 3),
            number_cell(s.median),
            number_cell(s.iqr(), 3),
            number_cell(s.best),
            number_cell(s.worst),
            errors.empty() ? empty_cell() : number_cell(mean(errors), 4),
            has_target ? number_cell(static_cast<double>(successes) / total, 3) : empty_cell(),
            !has_target ? empty_cell() : (ert ? number_cell(*ert, 6) : text_cell("inf"))};
        for (double fraction : options.budget_fractions) {
            std::vector<double> values;
            for (const auto* r : g.runs)
                if (const double v = value_at_budget(*r, fraction * most_evaluations); !std::isnan(v))
                    values.push_back(v);
            row.push_back(values.empty() ? empty_cell() : number_cell(summarize(values).median));
        }
        t.add_row(std::move(row));
    }
    t.caption =
        "Std is the sample standard deviation (two-pass), IQR = q75 - q25 (linear interpolation, type 7). "
        "Success: the run reached the study's target (blank: no run on the problem reached one, or none was "
        "set); ERT = evaluations of all runs (to the target for "
        "successful ones) / successful runs, as COCO defines it. Budget columns: median best-so-far after "
        "that fraction of the largest evaluation count of the group.";
    return t;
}

Table tests_table(const std::vector<Comparison>& comparisons, const ComparisonOptions& options) {
    Table t;
    t.id = "tests";
    t.title = "Tests against the reference " + options.reference;
    t.header = {"Problem", "Algorithm", "Test", "W", "z", "p", "p (Holm)", "A12", "Result"};
    for (const auto& c : comparisons)
        t.add_row({text_cell(c.problem), text_cell(c.algorithm), text_cell(c.test.name),
                   number_cell(c.test.statistic, 6), c.test.exact ? empty_cell() : number_cell(c.test.z, 4),
                   number_cell(c.test.p_value, 3), number_cell(c.adjusted_p, 3), number_cell(c.a12, 3),
                   text_cell(c.marker)});
    t.caption =
        "Two-sided Wilcoxon rank-sum test (Mann-Whitney U; W = U of the algorithm) of each algorithm's "
        "final values against the reference's, Holm-adjusted across the comparisons of each problem, "
        "alpha = " +
        alpha_text(options.alpha) +
        ". A12 = Vargha-Delaney effect size P(algorithm > reference) + P(=)/2 (below 0.5: the algorithm "
        "tends to lower, better values). +: significantly better than the reference, -: significantly "
        "worse, =: no significant difference.";
    return t;
}

Table generic_table(const StudyIndex& index, const std::vector<Comparison>& comparisons,
                    const ComparisonOptions& options) {
    Table t;
    t.id = "comparison";
    t.title = "Final values: mean (std) per problem and algorithm";
    t.header = {"Problem"};
    for (const auto& a : index.algorithms())
        t.header.push_back(a == options.reference ? a + " (reference)" : a);
    std::size_t least_runs = SIZE_MAX;
    std::size_t most_runs = 0;
    for (const auto& p : index.problems()) {
        std::vector<TableCell> row = {text_cell(p)};
        double best = INFINITY;
        for (const auto& a : index.algorithms())
            if (const auto* g = index.find(p, a))
                best = std::min(best, mean(g->final_values()));
        for (const auto& a : index.algorithms()) {
            const auto* g = index.find(p, a);
            if (g == nullptr) {
                row.push_back(empty_cell());
                continue;
            }
            least_runs = std::min(least_runs, g->runs.size());
            most_runs = std::max(most_runs, g->runs.size());
            const Summary s = summarize(g->final_values());
            std::string marker;
            for (const auto& c : comparisons)
                if (c.problem == p && c.algorithm == a)
                    marker = " " + c.marker;
            TableCell cell{format_number(s.mean, 4) + " (" + format_number(s.std, 2) + ")" + marker, "",
                           s.mean == best};
            row.push_back(cell);
        }
        t.add_row(std::move(row));
    }
    const std::string runs = least_runs == most_runs || least_runs == SIZE_MAX
                                 ? std::to_string(most_runs)
                                 : std::to_string(least_runs) + "-" + std::to_string(most_runs);
    t.caption = "Mean (sample std) of the final best-so-far value over " + runs +
                " runs; lowest mean in bold. Markers against the reference " + options.reference +
                ": two-sided Wilcoxon rank-sum test (Mann-Whitney U), Holm correction across each problem's "
                "comparisons, alpha = " +
                alpha_text(options.alpha) + "; + better, - worse, = no significant difference.";
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
    t.title = "Across problems: Friedman average ranks and Wilcoxon signed-rank against " + options.reference;
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
            t.add_row({text_cell(algorithms[j] + " (reference)"), rank, empty_cell(), empty_cell(),
                       empty_cell(), empty_cell(), empty_cell()});
            continue;
        }
        t.add_row({text_cell(algorithms[j]), rank, number_cell(posthoc_adjusted[i], 3),
                   number_cell(signed_tests[j].statistic, 6), number_cell(signed_tests[j].p_value, 3),
                   number_cell(signed_adjusted[i], 3), text_cell(signed_tests[j].name)});
        ++i;
    }
    t.caption =
        "Over " + std::to_string(problems.size()) +
        " problems (per-problem medians of the final values; rank 1 = "
        "lowest). Friedman test: chi-square = " +
        format_number(friedman.chi_square, 5) + ", df = " + format_number(friedman.degrees_of_freedom) +
        ", p = " + format_number(friedman.p_value, 3) +
        ". Post-hoc: z = (R_j - R_ref) / sqrt(k(k+1)/(6N)) against the reference, Holm-adjusted. Wilcoxon "
        "signed-rank test of each algorithm's per-problem medians against the reference's, paired by "
        "problem, Holm-adjusted; alpha = " +
        alpha_text(options.alpha) + ".";
    return t;
}

} // namespace

std::optional<std::pair<std::vector<std::string>, std::vector<std::vector<double>>>>
per_problem_medians(const StudyIndex& index) {
    // Problems on which every algorithm has runs: the blocks of the Friedman test.
    std::vector<std::string> problems;
    for (const auto& p : index.problems())
        if (index.algorithms_on(p).size() == index.algorithms().size())
            problems.push_back(p);
    if (problems.size() < 2 || index.algorithms().size() < 2)
        return std::nullopt;
    std::vector<std::vector<double>> medians;
    for (const auto& p : problems) {
        std::vector<double> row;
        for (const auto& a : index.algorithms())
            row.push_back(summarize(index.find(p, a)->final_values()).median);
        medians.push_back(row);
    }
    return std::make_pair(problems, medians);
}

std::string resolve_reference(const StudyIndex& index, const std::optional<std::string>& requested) {
    const auto& algorithms = index.algorithms();
    if (algorithms.empty())
        throw std::invalid_argument("the study has no runs");
    std::string known;
    for (const auto& a : algorithms)
        known += (known.empty() ? "" : ", ") + a;
    if (!requested) {
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

std::vector<Table> comparison_tables(const StudyIndex& index, const ComparisonOptions& options) {
    std::vector<Table> tables;
    tables.push_back(summary_table(index, options));
    const auto comparisons = compare_with_reference(index, options);
    if (!comparisons.empty())
        tables.push_back(tests_table(comparisons, options));
    tables.push_back(generic_table(index, comparisons, options));
    if (auto across = across_problems_table(index, options))
        tables.push_back(std::move(*across));
    return tables;
}

} // namespace mhb
