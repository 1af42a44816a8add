// The paper's Table 3 "Parameter identification results": per algorithm the identified parameters
// (mean and std over runs), their % error against the truth and deviation from the least-squares
// optimum theta*, beside the paper's values, under the rows of the truth and theta* themselves.
#include <cmath>
#include <utility>

#include "results/analysis/statistics.hpp"
#include "results/tables/paper_common.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb::tables {

namespace {

// The rows hold different quantities, each formatted alike down a column: values (5 significant
// digits), spreads (2) and percentages (3 decimals), so each kind is a group of its own.
enum Kind { values = 0, spreads = 1, percents = 2, paper_values = 3, paper_percents = 4 };

// The quantity a row holds, shorter in LaTeX.
TableCell quantity_cell(const std::string& what) {
    static const std::pair<const char*, const char*> short_forms[] = {
        {"identified (mean)", "mean"},    {"std over runs", "std"},
        {"error % vs true", "error \\%"}, {"deviation % from theta*", "dev.\\ \\%"},
        {"paper identified", "paper"},    {"paper |error| %", "paper err.\\ \\%"}};
    for (const auto& [text, latex] : short_forms)
        if (what == text)
            return latex_text_cell(what, latex);
    return text_cell(what);
}

TableCell who_cell(const std::string& who) {
    return who == "theta* (least squares)" ? latex_text_cell(who, "$\\theta^*$ (LS)") : text_cell(who);
}

// 100 (v - reference) / reference per parameter; NaN (a blank cell) where the reference is 0.
std::vector<double> relative_pct(const std::vector<double>& v, const std::vector<double>& reference) {
    std::vector<double> out(v.size(), NAN);
    for (std::size_t k = 0; k < v.size() && k < reference.size(); ++k)
        if (reference[k] != 0.0)
            out[k] = 100.0 * (v[k] - reference[k]) / reference[k];
    return out;
}

// Table 3's rows as they are added: a value per parameter, formatted by the row's kind, and the
// Overall column.
struct ParameterRows {
    Table& table;
    const std::vector<std::string>& names;
    std::vector<int> paper_decimals;       // per parameter, of the paper's identified values
    std::vector<int> paper_error_decimals; // per parameter, of the paper's errors

    ParameterRows(Table& t, const std::vector<std::string>& parameter_names, const PmsmProblem& p)
        : table(t), names(parameter_names), paper_decimals(names.size(), 0),
          paper_error_decimals(names.size(), 0) {
        if (p.published == nullptr)
            return;
        for (const auto& entry : p.published->identification)
            for (std::size_t k = 0; k < names.size(); ++k)
                if (const int j = paper_parameter(names[k]); j >= 0) {
                    const auto at = static_cast<std::size_t>(j);
                    paper_decimals[k] = std::max(paper_decimals[k], printed_decimals(entry.identified[at]));
                    paper_error_decimals[k] =
                        std::max(paper_error_decimals[k], printed_decimals(entry.error_pct[at]));
                }
    }

    void add(const std::string& who, const std::string& what, const std::vector<double>& v, Kind kind,
             TableCell overall = empty_cell()) {
        std::vector<TableCell> row = {who_cell(who), quantity_cell(what)};
        for (std::size_t k = 0; k < names.size(); ++k) {
            if (k >= v.size() || !std::isfinite(v[k])) {
                row.push_back(empty_cell());
                continue;
            }
            TableCell cell = kind == percents         ? fixed_cell(v[k], 3)
                             : kind == paper_values   ? fixed_cell(v[k], paper_decimals[k])
                             : kind == paper_percents ? fixed_cell(v[k], paper_error_decimals[k])
                                                      : number_cell(v[k], kind == values ? 5 : 2);
            cell.group = kind;
            row.push_back(std::move(cell));
        }
        overall.group = percents;
        row.push_back(std::move(overall));
        table.add_row(std::move(row));
    }
};

// The mean over runs of the RMS relative distance of the best point to theta*, in %.
double mean_rms_deviation_pct(const RunGroup& g, const std::vector<double>& theta, std::size_t d) {
    std::vector<double> distances;
    for (const auto* r : g.runs) {
        double sum = 0.0;
        for (std::size_t k = 0; k < d && k < r->best_x.size() && k < theta.size(); ++k)
            sum += std::pow((r->best_x[k] - theta[k]) / theta[k], 2);
        distances.push_back(100.0 * std::sqrt(sum / static_cast<double>(d)));
    }
    return mean(distances);
}

// The paper's identified values and errors in the order of this problem's parameters.
void add_published_rows(ParameterRows& rows, const std::string& who,
                        const PublishedIdentification& published) {
    const std::size_t d = rows.names.size();
    std::vector<double> identified(d, NAN);
    std::vector<double> errors(d, NAN);
    for (std::size_t k = 0; k < d; ++k)
        if (const int j = paper_parameter(rows.names[k]); j >= 0) {
            identified[k] = published.identified[static_cast<std::size_t>(j)];
            errors[k] = published.error_pct[static_cast<std::size_t>(j)];
        }
    rows.add(who, "paper identified", identified, paper_values);
    rows.add(who, "paper |error| %", errors, paper_percents);
}

// One algorithm's rows: mean and std of each parameter, their errors, and the paper's values.
void add_parameter_error_rows(ParameterRows& rows, const StudyIndex& index, const PmsmProblem& p,
                              const std::string& algorithm, const RunRecord& first) {
    const RunGroup& g = *index.find(p.spec, algorithm);
    const std::size_t d = rows.names.size();
    const std::vector<double>& truth = first.true_parameters;
    const std::vector<double>& theta = first.x_opt;
    std::vector<double> means(d, NAN);
    std::vector<double> stds(d, NAN);
    for (std::size_t k = 0; k < d; ++k) {
        std::vector<double> v;
        for (const auto* r : g.runs)
            if (k < r->best_x.size())
                v.push_back(r->best_x[k]);
        if (!v.empty()) {
            means[k] = mean(v);
            stds[k] = standard_deviation(v);
        }
    }
    const std::string who = index.label(algorithm);
    rows.add(who, "identified (mean)", means, values);
    rows.add(who, "std over runs", stds, spreads);
    if (!truth.empty())
        rows.add(who, "error % vs true", relative_pct(means, truth), percents);
    if (!theta.empty())
        rows.add(who, "deviation % from theta*", relative_pct(means, theta), percents,
                 fixed_cell(mean_rms_deviation_pct(g, theta, d), 3));
    if (const auto* published = published_identification(p, algorithm))
        add_published_rows(rows, who, *published);
}

// What the rows are, said briefly (the LaTeX note).
const char* parameter_note =
    "Mean and sample std over runs of each run's best point; error % = 100 (mean - true) / "
    "true; dev. % the same against the least-squares optimum theta*.";

std::string parameter_caption(const StudyIndex& index, const PmsmProblem& p) {
    return "Problem: " + p.spec + ". Identified parameters over " + runs_note(index, p.spec) +
           ": mean and sample std of the best point of each run; error % = 100 (mean - true) / true. theta* "
           "is the exact least-squares (LS) optimum (what no optimiser can beat); deviation % (dev. %) = 100 "
           "(mean - theta*) / theta*, and Overall is the mean over runs of the RMS relative distance to "
           "theta* in %. Percentages to 3 decimals." +
           (p.published != nullptr ? " Paper values: " + paper_source(p) +
                                         " (its errors, paper err. %, are magnitudes)" + paper_rows_note + "."
                                   : std::string()) +
           left_out_notes(index);
}

} // namespace

Table parameter_table(const StudyIndex& index, const PmsmProblem& p) {
    const auto algorithms = index.algorithms_on(p.spec);
    const RunRecord& first = *index.find(p.spec, algorithms.front())->runs.front();
    const std::vector<std::string>& names = first.parameter_names;
    Table t;
    const bool paper = p.published != nullptr;
    t.id = (paper ? "table3_parameters" : "parameters") + p.suffix;
    t.title =
        (paper ? "Table 3: Parameter identification results (" : "Identified parameters (") + p.name + ")";
    t.header = {"Algorithm", "Quantity"};
    for (const auto& n : names)
        t.header.push_back(n);
    t.header.push_back("Overall");

    ParameterRows rows(t, names, p);
    const std::vector<double>& truth = first.true_parameters;
    const std::vector<double>& theta = first.x_opt;
    if (!truth.empty())
        rows.add("True value", "value", truth, values);
    if (!theta.empty()) {
        rows.add("theta* (least squares)", "value", theta, values);
        if (!truth.empty())
            rows.add("theta* (least squares)", "error % vs true", relative_pct(theta, truth), percents);
    }
    for (const auto& a : algorithms)
        add_parameter_error_rows(rows, index, p, a, first);
    t.caption = parameter_caption(index, p);
    t.latex_note = parameter_note;
    t.latex_column(0).heading = true; // each algorithm heads its rows: a column less
    t.latex_column(1).key = true;
    for (std::size_t k = 0; k < names.size(); ++k)
        t.latex_column(2 + k).header = parameter_latex(names[k]);
    format_columns(t);
    return t;
}

} // namespace mhb::tables
