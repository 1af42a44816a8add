#include "results/paper_tables.hpp"

#include <cctype>
#include <cmath>

#include "results/published_pmsm.hpp"
#include "results/statistics.hpp"

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
            number_cell(mean(evaluations), 6), number_cell(s.mean), number_cell(s.std)};
        row[3].bold = std::isfinite(best_mean) && s.mean == best_mean;
        if (const auto* f = published_fitness(p, a)) {
            row.push_back(number_cell(f->mean));
            row.push_back(number_cell(f->std));
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

    const auto values_row = [&](const std::string& who, const std::string& what, const std::vector<double>& v,
                                int digits, TableCell overall) {
        std::vector<TableCell> row = {text_cell(who), text_cell(what)};
        for (std::size_t k = 0; k < d; ++k)
            row.push_back(k < v.size() && std::isfinite(v[k]) ? number_cell(v[k], digits) : empty_cell());
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
        values_row("True value", "", truth, 5, empty_cell());
    if (!theta.empty()) {
        values_row("theta* (least squares)", "value", theta, 5, empty_cell());
        if (!truth.empty())
            values_row("theta* (least squares)", "error % vs true", relative_pct(theta, truth), 3,
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
        values_row(who, "identified (mean)", means, 5, empty_cell());
        values_row(who, "std over runs", stds, 3, empty_cell());
        if (!truth.empty())
            values_row(who, "error % vs true", relative_pct(means, truth), 3, empty_cell());
        if (!theta.empty()) {
            std::vector<double> distances;
            for (const auto* r : g.runs) {
                double sum = 0.0;
                for (std::size_t k = 0; k < d && k < r->best_x.size() && k < theta.size(); ++k)
                    sum += std::pow((r->best_x[k] - theta[k]) / theta[k], 2);
                distances.push_back(100.0 * std::sqrt(sum / static_cast<double>(d)));
            }
            values_row(who, "deviation % from theta*", relative_pct(means, theta), 3,
                       number_cell(mean(distances), 3));
        }
        if (const auto* published = published_identification(p, a)) {
            std::vector<double> identified(d, NAN);
            std::vector<double> errors(d, NAN);
            for (std::size_t k = 0; k < d; ++k)
                if (const int j = paper_parameter(names[k]); j >= 0) {
                    identified[k] = published->identified[static_cast<std::size_t>(j)];
                    errors[k] = published->error_pct[static_cast<std::size_t>(j)];
                }
            values_row(who, "paper identified", identified, 5, empty_cell());
            values_row(who, "paper |error| %", errors, 3, empty_cell());
        }
    }
    t.caption =
        "Identified parameters over " + runs_note(index, p.spec) +
        ": mean and sample std of the best x of each run; error % = 100 (mean - true) / true. theta* "
        "is the exact least-squares optimum (what no optimiser can beat); deviation % = 100 (mean - "
        "theta*) / theta*, and Overall is the mean over runs of the RMS relative distance to theta* in %. "
        "Paper values: " +
        std::string(paper_citation) + (p.published ? ", " + std::string(p.published->table) : "") +
        " (its errors are magnitudes)" + paper_rows_note + "." + left_out_notes(index);
    return t;
}

std::string value_and_error(double value, double error_pct) {
    return format_number(value, 4) + " / " + format_fixed(error_pct, 1) + "%";
}

Table conditions_table(const StudyIndex& index, const std::vector<PmsmProblem>& problems) {
    Table t;
    t.id = "table4_conditions";
    t.title = "Table 4: Identification results under different working conditions";
    t.header = {"Condition", "Algorithm", "Source"};
    for (const auto& n : pmsm_parameter_names)
        t.header.push_back(std::string(n));
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
                row.push_back(text_cell(value_and_error(m, 100.0 * std::fabs(m - truth) / truth)));
            }
            t.add_row(std::move(row));
            if (const auto* published = published_identification(p, a)) {
                std::vector<TableCell> paper_row = {text_cell(condition), text_cell(index.label(a)),
                                                    text_cell("paper")};
                for (std::size_t j = 0; j < pmsm_parameter_names.size(); ++j)
                    paper_row.push_back(
                        text_cell(value_and_error(published->identified[j], published->error_pct[j])));
                t.add_row(std::move(paper_row));
            }
        }
    }
    t.caption =
        "Identified value / |error| against the true value, this study (mean over runs) beside the paper's "
        "Table 4 (" +
        std::string(paper_citation) + ")" + paper_rows_note + ".";
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
