#include "results/analysis/relative_gaps.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "results/analysis/budget_target.hpp"
#include "results/analysis/statistics.hpp"
#include "results/store/csv.hpp"

namespace mhb {

namespace {

bool usable_optimum(const std::optional<double>& f_opt) {
    return f_opt && std::isfinite(*f_opt) && *f_opt != 0.0;
}

// The f* of a problem's runs: that of its first successful run that knows one.
std::optional<double> problem_optimum(const StudyIndex& index, const std::string& problem) {
    for (const auto& algorithm : index.algorithms())
        if (const RunGroup* g = index.find(problem, algorithm))
            for (const RunRecord* r : g->runs)
                if (r->f_opt)
                    return r->f_opt;
    return std::nullopt;
}

RelativeGapCell cell_of(const RunGroup* g) {
    RelativeGapCell cell;
    if (g == nullptr)
        return cell;
    cell.runs = g->runs.size();
    cell.failed = g->failed;
    std::vector<double> gaps;
    for (const RunRecord* r : g->runs) {
        cell.reached += r->evaluations_to_target ? 1U : 0U;
        if (const double gap = relative_gap(*r); !std::isnan(gap))
            gaps.push_back(gap);
    }
    if (!gaps.empty())
        cell.median = summarize(gaps).median;
    return cell;
}

} // namespace

double RelativeGapCell::success_rate() const {
    const std::size_t total = runs + failed;
    return total == 0 ? std::numeric_limits<double>::quiet_NaN()
                      : static_cast<double>(reached) / static_cast<double>(total);
}

std::vector<std::string> short_problem_names(const std::vector<std::string>& problems) {
    std::vector<SpecText> specs;
    for (const auto& p : problems)
        specs.push_back(split_spec_text(p));
    std::vector<std::string> names;
    for (const SpecText& spec : specs) {
        // The keys whose value differs between this family's problems (absent counts as a value).
        std::set<std::string> differing;
        for (const SpecText& other : specs) {
            if (other.name != spec.name)
                continue;
            for (const auto* a : {&spec, &other})
                for (const auto& [key, value] : a->parameters) {
                    const auto& b = a == &spec ? other : spec;
                    const auto it = b.parameters.find(key);
                    if (it == b.parameters.end() || it->second != value)
                        differing.insert(key);
                }
        }
        std::string name = spec.name;
        bool first = true;
        for (const auto& key : differing)
            if (const auto it = spec.parameters.find(key); it != spec.parameters.end()) {
                // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) of a separator string here.
                name.append(first ? " " : ",").append(key).append("=").append(it->second);
                first = false;
            }
        names.push_back(name);
    }
    // Two names alike (a family whose problems differ only by a key some lack): the specs themselves.
    for (std::size_t i = 0; i < names.size(); ++i)
        if (std::count(names.begin(), names.end(), names[i]) > 1)
            names[i] = problems[i];
    return names;
}

double relative_gap(const RunRecord& run) {
    if (!run.ok || !usable_optimum(run.f_opt))
        return std::numeric_limits<double>::quiet_NaN();
    return (run.best_f - *run.f_opt) / std::fabs(*run.f_opt);
}

std::optional<RelativeGaps> relative_gaps(const StudyIndex& index) {
    const auto target = budget_target(index.budget());
    if (!target || !target->relative)
        return std::nullopt;
    RelativeGaps gaps;
    for (const auto& problem : index.problems()) {
        const auto f_opt = problem_optimum(index, problem);
        if (usable_optimum(f_opt)) {
            gaps.problems.push_back(problem);
            gaps.f_opt.push_back(*f_opt);
        } else {
            gaps.left_out.push_back(problem);
        }
    }
    if (gaps.problems.size() < 2)
        return std::nullopt;
    gaps.names = short_problem_names(gaps.problems);
    gaps.algorithms = index.algorithms();
    for (const auto& algorithm : gaps.algorithms) {
        auto& row = gaps.cells.emplace_back();
        for (const auto& problem : gaps.problems)
            row.push_back(cell_of(index.group(problem, algorithm))); // all runs failed: still counted
    }
    return gaps;
}

std::string relative_gap_medians_csv(const StudyIndex& index, const RelativeGaps& gaps) {
    std::string out =
        "problem,name,algorithm,label,f_opt,runs,failed,median_relative_gap,reached,success_rate\n";
    for (std::size_t p = 0; p < gaps.problems.size(); ++p)
        for (std::size_t a = 0; a < gaps.algorithms.size(); ++a) {
            const RelativeGapCell& c = gaps.cells[a][p];
            const auto optional = [](double v) { return std::isnan(v) ? std::string() : csv_number(v); };
            out += csv_field(gaps.problems[p]) + ',' + csv_field(gaps.names[p]) + ',' +
                   csv_field(gaps.algorithms[a]) + ',' + csv_field(index.label(gaps.algorithms[a])) + ',' +
                   csv_number(gaps.f_opt[p]) + ',' + std::to_string(c.runs) + ',' + std::to_string(c.failed) +
                   ',' + optional(c.median) + ',' + std::to_string(c.reached) + ',' +
                   optional(c.success_rate()) + '\n';
        }
    return out;
}

} // namespace mhb
