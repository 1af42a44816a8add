#include "results/analysis/curve_data.hpp"

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <utility>

#include "results/analysis/evaluation_counts.hpp"
#include "results/analysis/relative_gaps.hpp" // short_problem_names
#include "results/analysis/statistics.hpp"
#include "results/store/csv.hpp" // CSV as the store writes it, for every room

namespace mhb {

namespace {

// One run's curve as a step function: (key, value) pairs with ascending keys.
using Steps = std::vector<std::pair<std::int64_t, double>>;

// Calls `emit(key, values)` for every key of the union of the runs' keys, with each run's value
// carried forward from its last key not after `key` (runs without such a key are left out).
void sample_union(const std::vector<Steps>& runs,
                  const std::function<void(std::int64_t, const std::vector<double>&)>& emit) {
    std::set<std::int64_t> keys;
    for (const auto& steps : runs)
        for (const auto& s : steps)
            keys.insert(s.first);
    std::vector<std::size_t> position(runs.size(), 0);
    std::vector<double> values;
    for (const std::int64_t key : keys) {
        values.clear();
        for (std::size_t r = 0; r < runs.size(); ++r) {
            const Steps& steps = runs[r];
            while (position[r] + 1 < steps.size() && steps[position[r] + 1].first <= key)
                ++position[r];
            if (!steps.empty() && steps[position[r]].first <= key)
                values.push_back(steps[position[r]].second);
        }
        if (!values.empty())
            emit(key, values);
    }
}

// A run's state at an iteration as every iteration file reads it: at the end of iteration k, or
// at the run's end if that came first. So the states are the end of every iteration the run
// completed, then, when it stopped inside an iteration (its budget or target reached there, or
// inside its initialisation), its final state at that iteration; carried forward from there on,
// a run that stopped counts with its final value at every later iteration.
struct IterationState {
    std::int64_t iteration = 0;
    std::int64_t evaluations = 0;
    double best_f = 0.0;
    const std::vector<double>* best_x = nullptr;
};

std::vector<IterationState> iteration_states(const RunRecord& r) {
    std::vector<IterationState> states;
    for (const auto& p : r.curve)
        states.push_back({p.iteration, p.evaluations, p.best_f, &p.best_x});
    if (states.empty() || r.evaluations > states.back().evaluations) {
        const std::int64_t stopped_in = states.empty() ? 0 : states.back().iteration + 1;
        states.push_back({stopped_in, r.evaluations, r.best_f, &r.best_x});
    }
    return states;
}

std::string prefix(const StudyIndex& index, const RunGroup& g) {
    return csv_field(g.problem) + ',' + csv_field(g.algorithm) + ',' + csv_field(index.label(g.algorithm)) +
           ',';
}

std::string summary_columns(const std::vector<double>& values) {
    const Summary s = summarize(values);
    return csv_number(s.mean) + ',' + csv_number(s.std) + ',' + csv_number(s.median) + ',' +
           csv_number(s.q25) + ',' + csv_number(s.q75);
}

} // namespace

std::string fitness_curves_by_iteration(const StudyIndex& index) {
    std::string out = "problem,algorithm,label,iteration,runs,evaluations_mean,mean,std,median,q25,q75\n";
    for (const auto& g : index.groups()) {
        std::vector<Steps> fitness;
        std::vector<Steps> evaluations;
        for (const auto* r : g.runs) {
            Steps f;
            Steps e;
            for (const auto& state : iteration_states(*r)) {
                f.emplace_back(state.iteration, state.best_f);
                e.emplace_back(state.iteration, static_cast<double>(state.evaluations));
            }
            fitness.push_back(std::move(f));
            evaluations.push_back(std::move(e));
        }
        std::vector<std::string> evaluation_means;
        sample_union(evaluations, [&](std::int64_t, const std::vector<double>& v) {
            evaluation_means.push_back(csv_number(mean(v)));
        });
        std::size_t row = 0;
        sample_union(fitness, [&](std::int64_t iteration, const std::vector<double>& v) {
            out += prefix(index, g) + std::to_string(iteration) + ',' + std::to_string(v.size()) + ',' +
                   evaluation_means[row++] + ',' + summary_columns(v) + '\n';
        });
    }
    return out;
}

std::string fitness_curves_by_evaluations(const StudyIndex& index) {
    std::string out = "problem,algorithm,label,evaluations,runs,mean,std,median,q25,q75\n";
    std::vector<double> values;
    for (const auto& g : index.groups()) {
        // The x-axis: every count of the shared grid a run of the group reached, and each run's last.
        std::set<std::int64_t> keys;
        for (const auto* r : g.runs)
            for (const auto& c : r->checkpoints)
                keys.insert(c.evaluations);
        for (const std::int64_t evaluations : keys) {
            values.clear();
            for (const auto* r : g.runs)
                if (const double v = value_at_evaluations(*r, evaluations); !std::isnan(v))
                    values.push_back(v);
            if (values.empty())
                continue;
            out += prefix(index, g) + std::to_string(evaluations) + ',' + std::to_string(values.size()) +
                   ',' + summary_columns(values) + '\n';
        }
    }
    return out;
}

std::string parameter_curves_by_iteration(const StudyIndex& index) {
    std::string out = "problem,algorithm,label,parameter,iteration,runs,mean,std,true,opt\n";
    for (const auto& g : index.groups()) {
        if (g.runs.empty() || g.runs.front()->parameter_names.empty())
            continue;
        const RunRecord& first = *g.runs.front();
        for (std::size_t k = 0; k < first.parameter_names.size(); ++k) {
            std::vector<Steps> runs;
            for (const auto* r : g.runs) {
                Steps s;
                for (const auto& state : iteration_states(*r))
                    if (k < state.best_x->size())
                        s.emplace_back(state.iteration, (*state.best_x)[k]);
                runs.push_back(std::move(s));
            }
            const std::string truth =
                k < first.true_parameters.size() ? csv_number(first.true_parameters[k]) : "";
            const std::string optimum = k < first.x_opt.size() ? csv_number(first.x_opt[k]) : "";
            sample_union(runs, [&](std::int64_t iteration, const std::vector<double>& v) {
                out += prefix(index, g) + csv_field(first.parameter_names[k]) + ',' +
                       std::to_string(iteration) + ',' + std::to_string(v.size()) + ',' +
                       csv_number(mean(v)) + ',' + csv_number(standard_deviation(v)) + ',' + truth + ',' +
                       optimum + '\n';
            });
        }
    }
    return out;
}

std::string final_values(const StudyIndex& index) {
    std::string out = "problem,algorithm,label,run,best_f,evaluations,evals_to_target\n";
    for (const auto& g : index.groups())
        for (const auto* r : g.runs)
            out += prefix(index, g) + std::to_string(r->run_index) + ',' + csv_number(r->best_f) + ',' +
                   std::to_string(r->evaluations) + ',' +
                   (r->evaluations_to_target ? std::to_string(*r->evaluations_to_target) : "") + '\n';
    return out;
}

std::string problem_facts(const StudyIndex& index) {
    std::map<std::string, std::string> f_opts; // every run of a problem knows the same f*, or none
    for (const auto& g : index.groups())
        for (const auto* r : g.runs)
            if (r->f_opt)
                f_opts.emplace(g.problem, csv_number(*r->f_opt));
    const std::vector<std::string> names = short_problem_names(index.problems());
    std::string out = "problem,name,f_opt\n";
    for (std::size_t p = 0; p < index.problems().size(); ++p) {
        const auto known = f_opts.find(index.problems()[p]);
        out += csv_field(index.problems()[p]) + ',' + csv_field(names[p]) + ',' +
               (known == f_opts.end() ? std::string() : known->second) + '\n';
    }
    return out;
}

const std::vector<double>& ecdf_target_gaps() {
    static const std::vector<double> gaps = {1e2, 1e1, 1e0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
    return gaps;
}

std::string target_hits(const StudyIndex& index) {
    std::string out = "problem,algorithm,label,run,target_gap,evaluations\n";
    for (const auto& g : index.groups())
        for (const auto* r : g.runs) {
            if (!r->f_opt)
                continue;
            const double f_opt = *r->f_opt;
            for (const double gap : ecdf_target_gaps()) {
                const auto hit = first_evaluation_reaching(*r, [&](double f) { return f - f_opt <= gap; });
                out += prefix(index, g) + std::to_string(r->run_index) + ',' + csv_number(gap) + ',' +
                       (hit ? std::to_string(*hit) : "") + '\n';
            }
        }
    return out;
}

} // namespace mhb
