#include "results/tables/paper_tables.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "results/analysis/statistics.hpp"
#include "results/store/csv.hpp"
#include "results/tables/published_pmsm.hpp"

namespace mhb {

namespace {

const char* const paper_citation = "Li, Wang, Ji (2017), J. System Simulation 29(2):393-401";

struct PmsmProblem {
    std::string spec;
    const PublishedCondition* published = nullptr; // nullptr: a condition the paper did not run
    std::string suffix;                            // "" for the paper's Table 2/3 condition
};

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

// The paper's entry for this algorithm, if any: only for the configurations the paper ran, i.e. the
// canonical spec exactly "itlbo", "tlbo" or "pso" (every parameter at its default, which are the
// paper's settings). A variant (itlbo:obl=off, pso:w=0.7, a grid point) gets none, whatever its name.
template <typename Entry>
const Entry* published_entry(const std::vector<Entry>& entries, const std::string& algorithm) {
    for (const auto& e : entries)
        if (e.algorithm == algorithm)
            return &e;
    return nullptr;
}

const PublishedFitness* published_fitness(const PmsmProblem& p, const std::string& algorithm) {
    return p.published == nullptr ? nullptr : published_entry(p.published->fitness, algorithm);
}

const PublishedIdentification* published_identification(const PmsmProblem& p, const std::string& algorithm) {
    return p.published == nullptr ? nullptr : published_entry(p.published->identification, algorithm);
}

// Index of parameter `name` in the paper's order, or -1.
int paper_parameter(const std::string& name) {
    for (std::size_t k = 0; k < pmsm_parameter_names.size(); ++k)
        if (pmsm_parameter_names[k] == name)
            return static_cast<int>(k);
    return -1;
}

// Where the paper's numbers appear, and what they were measured with.
const char* const paper_rows_note =
    "; shown only beside itlbo, tlbo and pso with every parameter at its default (the paper's settings), "
    "never beside a variant; the paper ran NP = 50 for 150 iterations, 20 runs";

TableCell empty_cell() {
    return text_cell("");
}

// A PMSM parameter as the paper writes it: Rs -> $R_s$, psi -> $\psi_f$ (flux linkage).
std::string parameter_latex(const std::string& name) {
    if (name == "Rs")
        return "$R_s$";
    if (name == "Ld")
        return "$L_d$";
    if (name == "Lq")
        return "$L_q$";
    if (name == "psi")
        return "$\\psi_f$";
    return "";
}

// Digits after the point of a published value as the paper prints it (its shortest decimal form):
// a column of published values shows them with the most any of them has, which is exact for every
// one and adds no digit the paper did not print.
int printed_decimals(double value) {
    const std::string text = csv_number(value);
    const std::size_t e = text.find_first_of("eE");
    const std::string mantissa = text.substr(0, e);
    const std::size_t point = mantissa.find('.');
    int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
    if (e != std::string::npos)
        decimals -= std::atoi(text.c_str() + e + 1);
    return std::max(0, decimals);
}

TableCell latex_text_cell(std::string text, std::string latex) {
    TableCell cell = text_cell(std::move(text));
    cell.latex = std::move(latex);
    return cell;
}

std::size_t total_runs(const RunGroup& g) {
    return g.runs.size() + g.failed;
}

std::string runs_note(const StudyIndex& index, const std::string& problem) {
    std::size_t least = 0;
    std::size_t most = 0;
    bool first = true;
    for (const auto& a : index.algorithms_on(problem)) {
        const std::size_t n = index.find(problem, a)->runs.size();
        least = first ? n : std::min(least, n);
        most = first ? n : std::max(most, n);
        first = false;
    }
    return least == most ? std::to_string(least) + " runs per algorithm"
                         : std::to_string(least) + "-" + std::to_string(most) + " runs per algorithm";
}

Table fitness_table(const StudyIndex& index, const PmsmProblem& p) {
    Table t;
    t.id = "table2_fitness" + p.suffix;
    t.title = "Table 2: Fitness of different algorithms (" + p.spec + ")";
    t.header = {"Algorithm",  "Runs",      "Evaluations (mean)", "Mean f", "Std f",
                "Paper mean", "Paper std", "Mean gap f - f*",    "f*"};
    const auto algorithms = index.algorithms_on(p.spec);
    int mean_decimals = 0;
    int std_decimals = 0;
    if (p.published != nullptr)
        for (const auto& f : p.published->fitness) {
            mean_decimals = std::max(mean_decimals, printed_decimals(f.mean));
            std_decimals = std::max(std_decimals, printed_decimals(f.std));
        }
    double best_mean = INFINITY;
    for (const auto& a : algorithms)
        best_mean = std::min(best_mean, mean(index.find(p.spec, a)->final_values()));
    for (const auto& a : algorithms) {
        const RunGroup& g = *index.find(p.spec, a);
        const Summary s = summarize(g.final_values());
        std::vector<double> evaluations;
        std::vector<double> gaps;
        std::vector<double> optima;
        for (const auto* r : g.runs) {
            evaluations.push_back(static_cast<double>(r->evaluations));
            if (r->error()) {
                gaps.push_back(*r->error());
                optima.push_back(*r->f_opt);
            }
        }
        std::vector<TableCell> row = {
            text_cell(index.label(a)),
            text_cell(std::to_string(g.runs.size()) + "/" + std::to_string(total_runs(g))),
            fixed_cell(mean(evaluations), 1), number_cell(s.mean, 4), number_cell(s.std, 3)};
        row[3].bold = std::isfinite(best_mean) && s.mean == best_mean;
        if (const auto* f = published_fitness(p, a)) {
            row.push_back(fixed_cell(f->mean, mean_decimals));
            row.push_back(fixed_cell(f->std, std_decimals));
        } else {
            row.push_back(empty_cell());
            row.push_back(empty_cell());
        }
        row.push_back(gaps.empty() ? empty_cell() : number_cell(mean(gaps), 4));
        row.push_back(optima.empty() ? empty_cell() : number_cell(mean(optima), 6));
        t.add_row(std::move(row));
    }
    for (const auto& a : index.algorithms()) { // every run failed: a row that says so
        const RunGroup* g = index.group(p.spec, a);
        if (g == nullptr || !g->runs.empty())
            continue;
        std::vector<TableCell> row(t.header.size(), empty_cell());
        row[0] = text_cell(index.label(a));
        row[1] = text_cell("0/" + std::to_string(g->failed));
        row[3] = text_cell("no successful run (" + std::to_string(g->failed) + " failed)");
        t.add_row(std::move(row));
    }
    t.caption = "Final best fitness over " + runs_note(index, p.spec) +
                " (mean, sample std); lowest mean in bold. f* is the exact least-squares optimum of the "
                "problem; the gap f - f* is what an optimiser could still gain. Paper values: " +
                std::string(paper_citation) + (p.published ? ", " + std::string(p.published->table) : "") +
                paper_rows_note + "." + left_out_notes(index);
    t.latex_column(1).group = "this study";
    t.latex_column(2).group = "this study";
    t.latex_column(3).group = "this study";
    t.latex_column(4).group = "this study";
    t.latex_column(5).group = "paper";
    t.latex_column(6).group = "paper";
    t.latex_column(7).group = "optimum";
    t.latex_column(8).group = "optimum";
    t.latex_column(1).fold_constant = true; // "20/20" on every row, typically
    t.latex_column(2).header = "Evals.\\\\(mean)";
    t.latex_column(3).header = "Mean $f$";
    t.latex_column(4).header = "Std $f$";
    t.latex_column(5).header = "Paper\\\\mean";
    t.latex_column(6).header = "Paper\\\\std";
    t.latex_column(7).header = "Mean gap\\\\$f - f^*$";
    t.latex_column(8).header = "$f^*$";
    t.latex_column(8).fold_constant = true;
    format_columns(t);
    return t;
}

Table parameter_table(const StudyIndex& index, const PmsmProblem& p) {
    const auto algorithms = index.algorithms_on(p.spec);
    const RunRecord& first = *index.find(p.spec, algorithms.front())->runs.front();
    const std::vector<std::string>& names = first.parameter_names;
    Table t;
    t.id = "table3_parameters" + p.suffix;
    t.title = "Table 3: Parameter identification results (" + p.spec + ")";
    t.header = {"Algorithm", "Quantity"};
    for (const auto& n : names)
        t.header.push_back(n);
    t.header.push_back("Overall");
    const std::size_t d = names.size();

    // The rows hold different quantities, each formatted alike down a column: values (5 significant
    // digits), spreads (2) and percentages (3 decimals), so each kind is a group of its own.
    enum Kind { values = 0, spreads = 1, percents = 2, paper_values = 3, paper_percents = 4 };
    std::vector<int> paper_decimals(d, 0);
    std::vector<int> paper_error_decimals(d, 0);
    if (p.published != nullptr)
        for (const auto& entry : p.published->identification)
            for (std::size_t k = 0; k < d; ++k)
                if (const int j = paper_parameter(names[k]); j >= 0) {
                    const auto at = static_cast<std::size_t>(j);
                    paper_decimals[k] = std::max(paper_decimals[k], printed_decimals(entry.identified[at]));
                    paper_error_decimals[k] =
                        std::max(paper_error_decimals[k], printed_decimals(entry.error_pct[at]));
                }
    const auto quantity = [](const std::string& what) {
        static const std::pair<const char*, const char*> short_forms[] = {
            {"identified (mean)", "mean"},    {"std over runs", "std"},
            {"error % vs true", "error \\%"}, {"deviation % from theta*", "dev.\\ \\%"},
            {"paper identified", "paper"},    {"paper |error| %", "paper err.\\ \\%"}};
        for (const auto& [text, latex] : short_forms)
            if (what == text)
                return latex_text_cell(what, latex);
        return text_cell(what);
    };
    const auto who_cell = [](const std::string& who) {
        return who == "theta* (least squares)" ? latex_text_cell(who, "$\\theta^*$ (LS)") : text_cell(who);
    };
    const auto values_row = [&](const std::string& who, const std::string& what, const std::vector<double>& v,
                                Kind kind, TableCell overall) {
        std::vector<TableCell> row = {who_cell(who), quantity(what)};
        for (std::size_t k = 0; k < d; ++k) {
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
        t.add_row(std::move(row));
    };
    const auto relative_pct = [](const std::vector<double>& v, const std::vector<double>& reference) {
        std::vector<double> out(v.size(), NAN);
        for (std::size_t k = 0; k < v.size() && k < reference.size(); ++k)
            if (reference[k] != 0.0)
                out[k] = 100.0 * (v[k] - reference[k]) / reference[k];
        return out;
    };
    const std::vector<double>& truth = first.true_parameters;
    const std::vector<double>& theta = first.x_opt;
    if (!truth.empty())
        values_row("True value", "value", truth, values, empty_cell());
    if (!theta.empty()) {
        values_row("theta* (least squares)", "value", theta, values, empty_cell());
        if (!truth.empty())
            values_row("theta* (least squares)", "error % vs true", relative_pct(theta, truth), percents,
                       empty_cell());
    }
    for (const auto& a : algorithms) {
        const RunGroup& g = *index.find(p.spec, a);
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
        const std::string who = index.label(a);
        values_row(who, "identified (mean)", means, values, empty_cell());
        values_row(who, "std over runs", stds, spreads, empty_cell());
        if (!truth.empty())
            values_row(who, "error % vs true", relative_pct(means, truth), percents, empty_cell());
        if (!theta.empty()) {
            std::vector<double> distances;
            for (const auto* r : g.runs) {
                double sum = 0.0;
                for (std::size_t k = 0; k < d && k < r->best_x.size() && k < theta.size(); ++k)
                    sum += std::pow((r->best_x[k] - theta[k]) / theta[k], 2);
                distances.push_back(100.0 * std::sqrt(sum / static_cast<double>(d)));
            }
            values_row(who, "deviation % from theta*", relative_pct(means, theta), percents,
                       fixed_cell(mean(distances), 3));
        }
        if (const auto* published = published_identification(p, a)) {
            std::vector<double> identified(d, NAN);
            std::vector<double> errors(d, NAN);
            for (std::size_t k = 0; k < d; ++k)
                if (const int j = paper_parameter(names[k]); j >= 0) {
                    identified[k] = published->identified[static_cast<std::size_t>(j)];
                    errors[k] = published->error_pct[static_cast<std::size_t>(j)];
                }
            values_row(who, "paper identified", identified, paper_values, empty_cell());
            values_row(who, "paper |error| %", errors, paper_percents, empty_cell());
        }
    }
    t.caption =
        "Identified parameters over " + runs_note(index, p.spec) +
        ": mean and sample std of the best point of each run; error % = 100 (mean - true) / true. theta* "
        "is the exact least-squares (LS) optimum (what no optimiser can beat); deviation % (dev. %) = 100 "
        "(mean - theta*) / theta*, and Overall is the mean over runs of the RMS relative distance to theta* "
        "in %. Percentages to 3 decimals. Paper values: " +
        std::string(paper_citation) + (p.published ? ", " + std::string(p.published->table) : "") +
        " (its errors, paper err. %, are magnitudes)" + paper_rows_note + "." + left_out_notes(index);
    t.latex_column(0).heading = true; // each algorithm heads its rows: a column less
    t.latex_column(1).key = true;
    for (std::size_t k = 0; k < d; ++k)
        t.latex_column(2 + k).header = parameter_latex(names[k]);
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

Table conditions_table(const StudyIndex& index, const std::vector<PmsmProblem>& problems) {
    Table t;
    t.id = "table4_conditions";
    t.title = "Table 4: Identification results under different working conditions";
    t.header = {"Condition", "Algorithm", "Source"};
    for (const auto& n : pmsm_parameter_names)
        t.header.push_back(std::string(n));
    // The paper's values with the decimals it printed (per parameter, over its conditions).
    std::array<int, pmsm_parameter_names.size()> paper_decimals{};
    for (const auto& p : problems)
        if (p.published != nullptr)
            for (const auto& entry : p.published->identification)
                for (std::size_t j = 0; j < paper_decimals.size(); ++j)
                    paper_decimals[j] = std::max(paper_decimals[j], printed_decimals(entry.identified[j]));
    for (const auto& p : problems) {
        if (p.published == nullptr)
            continue;
        const std::string condition =
            format_number(p.published->load) + " N m, " + format_number(p.published->speed) + " rpm";
        for (const auto& a : index.algorithms_on(p.spec)) {
            const RunGroup& g = *index.find(p.spec, a);
            const RunRecord& first = *g.runs.front();
            std::vector<TableCell> row = {text_cell(condition), text_cell(index.label(a)),
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
            t.add_row(std::move(row));
            if (const auto* published = published_identification(p, a)) {
                std::vector<TableCell> paper_row = {text_cell(condition), text_cell(index.label(a)),
                                                    text_cell("paper")};
                for (std::size_t j = 0; j < pmsm_parameter_names.size(); ++j)
                    paper_row.push_back(value_and_error(published->identified[j], published->error_pct[j],
                                                        {1, paper_decimals[j]}, 1));
                t.add_row(std::move(paper_row));
            }
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

std::vector<Table> pmsm_paper_tables(const StudyIndex& index) {
    std::vector<Table> tables;
    const auto problems = pmsm_problems(index);
    bool any_published = false;
    for (const auto& p : problems) {
        const auto algorithms = index.algorithms_on(p.spec);
        if (algorithms.empty())
            continue;
        tables.push_back(fitness_table(index, p));
        if (!index.find(p.spec, algorithms.front())->runs.front()->parameter_names.empty())
            tables.push_back(parameter_table(index, p));
        any_published = any_published || p.published != nullptr;
    }
    if (any_published)
        tables.push_back(conditions_table(index, problems));
    return tables;
}

} // namespace mhb
