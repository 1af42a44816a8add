// The paper's Tables 2 ("Fitness of different algorithms") and 4 ("Identification results under
// different working conditions") for the PMSM problems of a study, and pmsm_paper_tables(), which
// adds Table 3 (paper_parameter_table.cpp) for each problem whose runs identify parameters.
#include "results/tables/paper_tables.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include "results/analysis/statistics.hpp"
#include "results/store/csv.hpp" // CSV as the store writes it, for every room
#include "results/tables/paper_common.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb::tables {

namespace {

std::string file_slug(const std::string& text) {
    std::string out;
    for (char c : text)
        out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return out;
}

std::vector<PmsmProblem> pmsm_problems(const StudyIndex& index) {
    std::vector<PmsmProblem> out;
    for (const auto& p : index.problems()) {
        const SpecText spec = split_spec_text(p);
        if (spec.name != "pmsm")
            continue;
        PmsmProblem problem;
        problem.spec = p;
        const auto load = spec_number(spec, "load");
        const auto speed = spec_number(spec, "speed");
        if (load && speed)
            problem.published = find_published_condition(*load, *speed);
        const bool main_condition = problem.published != nullptr && !problem.published->fitness.empty();
        if (!main_condition)
            problem.suffix.append("_").append(file_slug(p));
        out.push_back(problem);
    }
    return out;
}

// The decimals the paper printed its fitness means and stds with (the most of any of its entries).
struct FitnessDecimals {
    int mean = 0;
    int std = 0;
};

FitnessDecimals paper_fitness_decimals(const PmsmProblem& p) {
    FitnessDecimals decimals;
    if (p.published != nullptr)
        for (const auto& f : p.published->fitness) {
            decimals.mean = std::max(decimals.mean, printed_decimals(f.mean));
            decimals.std = std::max(decimals.std, printed_decimals(f.std));
        }
    return decimals;
}

std::vector<TableCell> fitness_row(const StudyIndex& index, const PmsmProblem& p,
                                   const std::string& algorithm, double best_mean,
                                   const FitnessDecimals& decimals) {
    const RunGroup& g = *index.find(p.spec, algorithm);
    const Summary s = summarize(g.final_values());
    const std::vector<double> gaps = run_errors(g);
    std::vector<double> optima;
    for (const auto* r : g.runs)
        if (r->error())
            optima.push_back(*r->f_opt);
    std::vector<TableCell> row = {text_cell(index.label(algorithm)), text_cell(runs_text(g)),
                                  fixed_cell(mean(run_evaluations(g)), 1), number_cell(s.mean, 4),
                                  number_cell(s.std, 3)};
    row[3].bold = std::isfinite(best_mean) && s.mean == best_mean;
    if (const auto* f = published_fitness(p, algorithm)) {
        row.push_back(fixed_cell(f->mean, decimals.mean));
        row.push_back(fixed_cell(f->std, decimals.std));
    } else {
        row.push_back(empty_cell());
        row.push_back(empty_cell());
    }
    row.push_back(gaps.empty() ? empty_cell() : number_cell(mean(gaps), 4));
    row.push_back(optima.empty() ? empty_cell() : number_cell(mean(optima), 6));
    return row;
}

// An algorithm whose every run on the problem failed: a row that says so.
void add_failed_fitness_rows(Table& t, const StudyIndex& index, const PmsmProblem& p) {
    for (const auto& a : index.algorithms()) {
        const RunGroup* g = index.group(p.spec, a);
        if (g == nullptr || !g->runs.empty())
            continue;
        std::vector<TableCell> row(t.header.size(), empty_cell());
        row[0] = text_cell(index.label(a));
        row[1] = text_cell(runs_text(*g));
        row[3] = text_cell(no_successful_run_text(*g));
        t.add_row(std::move(row));
    }
}

void fitness_latex_layout(Table& t) {
    for (std::size_t c = 1; c <= 4; ++c)
        t.latex_column(c).group = "this study";
    t.latex_column(5).group = "paper";
    t.latex_column(6).group = "paper";
    t.latex_column(7).group = "optimum";
    t.latex_column(8).group = "optimum";
    t.latex_column(1).fold_constant = true; // "20/20" on every row, typically
    set_latex_headers(t, {{2, "Evals.\\\\(mean)"},
                          {3, "Mean $f$"},
                          {4, "Std $f$"},
                          {5, "Paper\\\\mean"},
                          {6, "Paper\\\\std"},
                          {7, "Mean gap\\\\$f - f^*$"},
                          {8, "$f^*$"}});
    t.latex_column(8).fold_constant = true;
}

Table fitness_table(const StudyIndex& index, const PmsmProblem& p) {
    Table t;
    t.id = "table2_fitness" + p.suffix;
    t.title = "Table 2: Fitness of different algorithms (" + p.spec + ")";
    t.header = {"Algorithm",  "Runs",      "Evaluations (mean)", "Mean f", "Std f",
                "Paper mean", "Paper std", "Mean gap f - f*",    "f*"};
    const auto algorithms = index.algorithms_on(p.spec);
    const FitnessDecimals decimals = paper_fitness_decimals(p);
    double best_mean = INFINITY;
    for (const auto& a : algorithms)
        best_mean = std::min(best_mean, mean(index.find(p.spec, a)->final_values()));
    for (const auto& a : algorithms)
        t.add_row(fitness_row(index, p, a, best_mean, decimals));
    add_failed_fitness_rows(t, index, p);
    t.caption = "Final best fitness over " + runs_note(index, p.spec) +
                " (mean, sample std); lowest mean in bold. f* is the exact least-squares optimum of the "
                "problem; the gap f - f* is what an optimiser could still gain. Paper values: " +
                paper_source(p) + paper_rows_note + "." + left_out_notes(index);
    fitness_latex_layout(t);
    format_columns(t);
    return t;
}

// "value / |error|%" as the paper's Table 4 prints it; the CSV keeps both at full precision.
TableCell value_and_error(double value, double error_pct, Digits value_digits, int group) {
    TableCell cell = spread_cell(value, error_pct, "", value_digits, {1, 1});
    cell.spread_style = SpreadStyle::slash_percent;
    cell.group = group;
    cell.value = csv_number(value) + " / " + csv_number(error_pct) + "%";
    return cell;
}

// The paper's values with the decimals it printed (per parameter, over its conditions).
using ParameterDecimals = std::array<int, pmsm_parameter_names.size()>;

ParameterDecimals paper_identification_decimals(const std::vector<PmsmProblem>& problems) {
    ParameterDecimals decimals{};
    for (const auto& p : problems)
        if (p.published != nullptr)
            for (const auto& entry : p.published->identification)
                for (std::size_t j = 0; j < decimals.size(); ++j)
                    decimals[j] = std::max(decimals[j], printed_decimals(entry.identified[j]));
    return decimals;
}

// The mean over runs of each of the paper's parameters with its |error| against the true value.
std::vector<TableCell> study_row(const StudyIndex& index, const RunGroup& g, const std::string& condition) {
    const RunRecord& first = *g.runs.front();
    std::vector<TableCell> row = {text_cell(condition), text_cell(index.label(g.algorithm)),
                                  text_cell("this study, mean of " + std::to_string(g.runs.size()))};
    for (std::size_t j = 0; j < pmsm_parameter_names.size(); ++j) {
        std::vector<double> v;
        std::size_t k = first.parameter_names.size();
        for (std::size_t i = 0; i < first.parameter_names.size(); ++i)
            if (first.parameter_names[i] == pmsm_parameter_names[j])
                k = i;
        for (const auto* r : g.runs)
            if (k < r->best_x.size())
                v.push_back(r->best_x[k]);
        if (v.empty() || k >= first.true_parameters.size() || first.true_parameters[k] == 0.0) {
            row.push_back(empty_cell());
            continue;
        }
        const double m = mean(v);
        const double truth = first.true_parameters[k];
        row.push_back(value_and_error(m, 100.0 * std::fabs(m - truth) / truth, {4, -1}, 0));
    }
    return row;
}

std::vector<TableCell> paper_row(const StudyIndex& index, const std::string& algorithm,
                                 const std::string& condition, const PublishedIdentification& published,
                                 const ParameterDecimals& decimals) {
    std::vector<TableCell> row = {text_cell(condition), text_cell(index.label(algorithm)),
                                  text_cell("paper")};
    for (std::size_t j = 0; j < pmsm_parameter_names.size(); ++j)
        row.push_back(value_and_error(published.identified[j], published.error_pct[j], {1, decimals[j]}, 1));
    return row;
}

Table conditions_table(const StudyIndex& index, const std::vector<PmsmProblem>& problems) {
    Table t;
    t.id = "table4_conditions";
    t.title = "Table 4: Identification results under different working conditions";
    t.header = {"Condition", "Algorithm", "Source"};
    for (const auto& n : pmsm_parameter_names)
        t.header.push_back(std::string(n));
    const ParameterDecimals paper_decimals = paper_identification_decimals(problems);
    for (const auto& p : problems) {
        if (p.published == nullptr)
            continue;
        const std::string condition =
            format_number(p.published->load) + " N m, " + format_number(p.published->speed) + " rpm";
        for (const auto& a : index.algorithms_on(p.spec)) {
            t.add_row(study_row(index, *index.find(p.spec, a), condition));
            if (const auto* published = published_identification(p, a))
                t.add_row(paper_row(index, a, condition, *published, paper_decimals));
        }
    }
    t.caption =
        "Identified value / |error| against the true value, this study (mean over runs) beside the paper's "
        "Table 4 (" +
        std::string(paper_citation) + ")" + paper_rows_note + ".";
    t.latex_column(0).fold_constant = true;
    t.latex_column(0).heading = true; // several conditions: each heads its rows
    t.latex_column(1).key = true;
    t.latex_column(2).key = true;
    for (std::size_t j = 0; j < pmsm_parameter_names.size(); ++j)
        t.latex_column(3 + j).header = parameter_latex(std::string(pmsm_parameter_names[j]));
    // The error on a line of its own under the value keeps the four parameters side by side.
    t.latex_spread_below = true;
    format_columns(t);
    return t;
}

} // namespace

} // namespace mhb::tables

namespace mhb {

std::vector<Table> pmsm_paper_tables(const StudyIndex& index) {
    std::vector<Table> out;
    const auto problems = tables::pmsm_problems(index);
    bool any_published = false;
    for (const auto& p : problems) {
        const auto algorithms = index.algorithms_on(p.spec);
        if (algorithms.empty())
            continue;
        out.push_back(tables::fitness_table(index, p));
        if (!index.find(p.spec, algorithms.front())->runs.front()->parameter_names.empty())
            out.push_back(tables::parameter_table(index, p));
        any_published = any_published || p.published != nullptr;
    }
    if (any_published)
        out.push_back(tables::conditions_table(index, problems));
    return out;
}

} // namespace mhb
