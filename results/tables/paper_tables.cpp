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

// The study's PMSM problems; with `paper`, each matched to the condition of the paper it ran.
std::vector<PmsmProblem> pmsm_problems(const StudyIndex& index, bool paper) {
    std::vector<PmsmProblem> out;
    for (const auto& p : index.problems()) {
        const SpecText spec = split_spec_text(p);
        if (spec.name != "pmsm")
            continue;
        PmsmProblem problem;
        problem.spec = p;
        problem.name = pmsm_problem_name(p);
        const auto load = spec_number(spec, "load");
        const auto speed = spec_number(spec, "speed");
        if (paper && load && speed)
            problem.published = find_published_condition(*load, *speed);
        out.push_back(problem);
    }
    // File names: the paper's Table 2/3 condition, or the only problem, has none; the others' name it.
    for (auto& problem : out) {
        const bool main_condition = problem.published != nullptr && !problem.published->fitness.empty();
        if (!main_condition && !(out.size() == 1 && problem.published == nullptr))
            problem.suffix.append("_").append(file_slug(problem.spec));
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
    if (p.published != nullptr) {
        const auto* f = published_fitness(p, algorithm);
        row.push_back(f != nullptr ? fixed_cell(f->mean, decimals.mean) : empty_cell());
        row.push_back(f != nullptr ? fixed_cell(f->std, decimals.std) : empty_cell());
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

// The columns after the runs: this study's, the paper's (when framed as the paper's), the optimum's.
void fitness_latex_layout(Table& t, bool paper) {
    const std::size_t optimum = paper ? 7 : 5;
    for (std::size_t c = 1; c <= 4; ++c)
        t.latex_column(c).group = "this study";
    if (paper) {
        t.latex_column(5).group = "paper";
        t.latex_column(6).group = "paper";
    }
    t.latex_column(optimum).group = "optimum";
    t.latex_column(optimum + 1).group = "optimum";
    t.latex_column(1).fold_constant = true; // "20/20" on every row, typically
    set_latex_headers(t, {{2, "Evals.\\\\(mean)"}, {3, "Mean $f$"}, {4, "Std $f$"}});
    if (paper)
        set_latex_headers(t, {{5, "Paper\\\\mean"}, {6, "Paper\\\\std"}});
    set_latex_headers(t, {{optimum, "Mean gap\\\\$f - f^*$"}, {optimum + 1, "$f^*$"}});
    t.latex_column(optimum + 1).fold_constant = true;
}

// What the rows are, said briefly (the LaTeX note); the full caption adds the paper's source.
std::string fitness_note(const StudyIndex& index, const PmsmProblem& p, bool cite_paper) {
    return "Final fitness over " + runs_note(index, p.spec) +
           " (mean, sample std); lowest mean in bold; f* the exact least-squares optimum." +
           (cite_paper && p.published != nullptr
                ? " Paper: " + std::string(p.published->table) + " of Li, Wang, Ji (2017)."
                : std::string());
}

Table fitness_table(const StudyIndex& index, const PmsmProblem& p) {
    const bool paper = p.published != nullptr;
    Table t;
    t.id = (paper ? "table2_fitness" : "fitness") + p.suffix;
    t.title =
        (paper ? "Table 2: Fitness of different algorithms (" : "Fitness of each algorithm (") + p.name + ")";
    t.header = {"Algorithm", "Runs", "Evaluations (mean)", "Mean f", "Std f"};
    if (paper)
        t.header.insert(t.header.end(), {"Paper mean", "Paper std"});
    t.header.insert(t.header.end(), {"Mean gap f - f*", "f*"});
    const auto algorithms = index.algorithms_on(p.spec);
    const FitnessDecimals decimals = paper_fitness_decimals(p);
    double best_mean = INFINITY;
    for (const auto& a : algorithms)
        best_mean = std::min(best_mean, mean(index.find(p.spec, a)->final_values()));
    for (const auto& a : algorithms)
        t.add_row(fitness_row(index, p, a, best_mean, decimals));
    add_failed_fitness_rows(t, index, p);
    t.latex_note = fitness_note(index, p, true);
    t.caption = "Problem: " + p.spec + ". " + fitness_note(index, p, false) +
                " The gap f - f* is what an optimiser could still gain." +
                (paper ? " Paper values: " + paper_source(p) + paper_rows_note + "." : std::string()) +
                left_out_notes(index);
    fitness_latex_layout(t, paper);
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
std::vector<TableCell> study_row(const StudyIndex& index, const RunGroup& g, const std::string& condition,
                                 bool paper) {
    const RunRecord& first = *g.runs.front();
    std::vector<TableCell> row = {text_cell(condition), text_cell(index.label(g.algorithm))};
    if (paper)
        row.push_back(text_cell("this study, mean of " + std::to_string(g.runs.size())));
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

// A problem's condition as the conditions table heads its rows: its name without "PMSM, ".
std::string condition_text(const PmsmProblem& p) {
    if (p.published != nullptr)
        return format_number(p.published->load) + " N m, " + format_number(p.published->speed) + " rpm";
    return p.name.rfind("PMSM, ", 0) == 0 ? p.name.substr(6) : p.name;
}

// Whether a problem's runs identify the paper's four parameters against known true values.
bool identifies_paper_parameters(const StudyIndex& index, const PmsmProblem& p) {
    const auto algorithms = index.algorithms_on(p.spec);
    if (algorithms.empty())
        return false;
    const RunRecord& first = *index.find(p.spec, algorithms.front())->runs.front();
    return !first.true_parameters.empty() && first.parameter_names.size() >= pmsm_parameter_names.size();
}

// The conditions side by side: the paper's Table 4 (with the published rows) when framed as the
// paper's, else the study's own; `problems` are those to show (two or more).
Table conditions_table(const StudyIndex& index, const std::vector<PmsmProblem>& problems, bool paper) {
    Table t;
    t.id = paper ? "table4_conditions" : "conditions";
    t.title = paper ? "Table 4: Identification results under different working conditions"
                    : "Identified parameters under each operating condition";
    t.header = {"Condition", "Algorithm"};
    if (paper)
        t.header.push_back("Source");
    for (const auto& n : pmsm_parameter_names)
        t.header.push_back(std::string(n));
    const ParameterDecimals paper_decimals = paper_identification_decimals(problems);
    for (const auto& p : problems) {
        const std::string condition = condition_text(p);
        for (const auto& a : index.algorithms_on(p.spec)) {
            t.add_row(study_row(index, *index.find(p.spec, a), condition, paper));
            if (const auto* published = paper ? published_identification(p, a) : nullptr)
                t.add_row(paper_row(index, a, condition, *published, paper_decimals));
        }
    }
    t.latex_note = "Identified value / |error| against the true value, mean over runs.";
    t.caption = t.latex_note;
    if (paper)
        t.caption +=
            " Beside the paper's Table 4 (" + std::string(paper_citation) + ")" + paper_rows_note + ".";
    const std::size_t first_parameter = paper ? 3 : 2;
    t.latex_column(0).fold_constant = true;
    t.latex_column(0).heading = true; // several conditions: each heads its rows
    for (std::size_t c = 1; c < first_parameter; ++c)
        t.latex_column(c).key = true;
    for (std::size_t j = 0; j < pmsm_parameter_names.size(); ++j)
        t.latex_column(first_parameter + j).header = parameter_latex(std::string(pmsm_parameter_names[j]));
    // The error on a line of its own under the value keeps the four parameters side by side.
    t.latex_spread_below = true;
    format_columns(t);
    return t;
}

// How many operating points (speed and load, or the simulated conditions, or the logged data) the
// problems have: a model or noise alone does not make another condition.
std::size_t operating_points(const std::vector<PmsmProblem>& problems) {
    std::vector<std::string> points;
    for (const auto& p : problems) {
        const SpecText spec = split_spec_text(p.spec);
        std::string point;
        for (const char* key : {"speed", "load", "conditions", "data"})
            if (const auto at = spec.parameters.find(key); at != spec.parameters.end())
                point += std::string(key) + "=" + at->second + ";";
        if (std::find(points.begin(), points.end(), point) == points.end())
            points.push_back(point);
    }
    return points.size();
}

// Every PMSM table of the study: fitness and parameters per problem, then the conditions side by
// side when two or more identify the paper's parameters (the paper's ones, when framed as its).
std::vector<Table> pmsm_identification_tables(const StudyIndex& index, bool paper) {
    std::vector<Table> out;
    const auto problems = pmsm_problems(index, paper);
    std::vector<PmsmProblem> conditions;
    for (const auto& p : problems) {
        const auto algorithms = index.algorithms_on(p.spec);
        if (algorithms.empty())
            continue;
        out.push_back(fitness_table(index, p));
        if (!index.find(p.spec, algorithms.front())->runs.front()->parameter_names.empty())
            out.push_back(parameter_table(index, p));
        // The paper's Table 4 holds only the conditions it ran; the study's own, every one.
        if (identifies_paper_parameters(index, p) && (!paper || p.published != nullptr))
            conditions.push_back(p);
    }
    if (operating_points(conditions) >= 2)
        out.push_back(conditions_table(index, conditions, paper));
    return out;
}

} // namespace

} // namespace mhb::tables

namespace mhb {

std::vector<Table> pmsm_tables(const StudyIndex& index) {
    return tables::pmsm_identification_tables(index, false);
}

std::vector<Table> pmsm_paper_tables(const StudyIndex& index) {
    return tables::pmsm_identification_tables(index, true);
}

bool is_pmsm_table_id(const std::string& id) {
    for (const char* table : {"table2_fitness", "table3_parameters", "table4_conditions", "fitness",
                              "parameters", "conditions"}) {
        const std::string name = table;
        if (id == name || id.rfind(name + "_pmsm", 0) == 0)
            return true;
    }
    return false;
}

bool is_paper_budget(const std::string& budget) {
    return budget == tables::paper_budget;
}

} // namespace mhb
