#include "results/store/study_index.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>

namespace mhb {

SpecText split_spec_text(const std::string& spec) {
    SpecText out;
    const auto colon = spec.find(':');
    out.name = spec.substr(0, colon);
    if (colon == std::string::npos)
        return out;
    std::size_t start = colon + 1;
    while (start <= spec.size()) {
        const auto comma = std::min(spec.find(',', start), spec.size());
        const std::string item = spec.substr(start, comma - start);
        const auto equals = item.find('=');
        if (equals != std::string::npos)
            out.parameters[item.substr(0, equals)] = item.substr(equals + 1);
        start = comma + 1;
    }
    return out;
}

std::optional<double> spec_number(const SpecText& spec, const std::string& key) {
    const auto it = spec.parameters.find(key);
    if (it == spec.parameters.end())
        return std::nullopt;
    double value = 0.0;
    const auto& text = it->second;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size())
        return std::nullopt;
    return value;
}

std::vector<std::string> study_budgets(const StudyData& data) {
    std::vector<std::string> budgets;
    for (const auto& r : data.runs)
        if (std::find(budgets.begin(), budgets.end(), r.budget) == budgets.end())
            budgets.push_back(r.budget);
    return budgets;
}

std::string budget_slug(const std::string& budget) {
    if (budget.empty())
        return "budget_unspecified";
    std::string out;
    for (char c : budget) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.';
        if (keep)
            out += c;
        else if (out.empty() || out.back() != '_')
            out += '_';
    }
    return out;
}

std::vector<double> RunGroup::final_values() const {
    std::vector<double> values;
    values.reserve(runs.size());
    for (const auto* r : runs)
        values.push_back(r->best_f);
    return values;
}

bool RunGroup::optimum_known() const {
    return !runs.empty() &&
           std::all_of(runs.begin(), runs.end(), [](const RunRecord* r) { return r->f_opt.has_value(); });
}

const RunRecord* RunGroup::run_with_index(std::int64_t run_index) const {
    const auto it = std::lower_bound(runs.begin(), runs.end(), run_index,
                                     [](const RunRecord* r, std::int64_t i) { return r->run_index < i; });
    return it != runs.end() && (*it)->run_index == run_index ? *it : nullptr;
}

PairedValues paired_values(const RunGroup& x, const RunGroup& y,
                           const std::function<double(const RunRecord&)>& of) {
    PairedValues out;
    for (const auto* r : x.runs)
        if (const RunRecord* partner = y.run_with_index(r->run_index)) {
            out.x.push_back(of(*r));
            out.y.push_back(of(*partner));
        }
    return out;
}

PairedValues paired_final_values(const RunGroup& x, const RunGroup& y) {
    return paired_values(x, y, [](const RunRecord& r) { return r.best_f; });
}

StudyIndex::StudyIndex(const StudyData& data, const std::optional<std::string>& budget) {
    if (budget) {
        budget_ = *budget;
    } else {
        const auto budgets = study_budgets(data);
        if (budgets.size() > 1)
            throw std::logic_error("StudyIndex: the study holds " + std::to_string(budgets.size()) +
                                   " budgets; index one budget at a time");
        if (!budgets.empty())
            budget_ = budgets.front();
    }
    std::vector<const RunRecord*> selected;
    for (const auto& r : data.runs)
        if (r.budget == budget_)
            selected.push_back(&r);

    const auto remember = [](std::vector<std::string>& list, const std::string& name) {
        if (std::find(list.begin(), list.end(), name) == list.end())
            list.push_back(name);
    };
    for (const auto* r : selected) {
        remember(problems_, r->problem);
        remember(algorithms_, r->algorithm);
    }
    for (const auto& info : data.algorithms) {
        labels_[info.spec] = info.label.empty() ? info.spec : info.label;
        full_specs_[info.spec] = info.full_spec.empty() ? info.spec : info.full_spec;
    }
    for (const auto& a : algorithms_) {
        labels_.emplace(a, a); // no-op where algorithms.csv named it
        full_specs_.emplace(a, a);
    }
    for (const auto& p : problems_)
        for (const auto& a : algorithms_) {
            RunGroup group;
            group.problem = p;
            group.algorithm = a;
            for (const auto* r : selected) {
                if (r->problem != p || r->algorithm != a)
                    continue;
                if (r->ok) {
                    group.runs.push_back(r);
                    infinite_ += std::isinf(r->best_f) ? 1U : 0U;
                    negative_infinite_ += std::isinf(r->best_f) && r->best_f < 0 ? 1U : 0U;
                } else {
                    ++group.failed;
                }
            }
            failed_ += group.failed;
            std::stable_sort(
                group.runs.begin(), group.runs.end(),
                [](const RunRecord* x, const RunRecord* y) { return x->run_index < y->run_index; });
            if (!group.runs.empty() || group.failed > 0)
                groups_.push_back(std::move(group));
        }
    for (const auto* r : selected)
        if (!r->ok)
            failed_records_.push_back(r);
    for (const auto& p : problems_) {
        std::map<std::int64_t, std::uint64_t> seed_of_index;
        std::set<std::string> algorithms;
        bool same = true;
        for (const auto* r : selected) {
            if (r->problem != p)
                continue;
            algorithms.insert(r->algorithm);
            const auto [it, inserted] = seed_of_index.emplace(r->run_index, r->seed);
            same = same && (inserted || it->second == r->seed);
        }
        paired_[p] = same && algorithms.size() >= 2;
    }
}

const RunGroup* StudyIndex::find(const std::string& problem, const std::string& algorithm) const {
    for (const auto& g : groups_)
        if (g.problem == problem && g.algorithm == algorithm)
            return g.runs.empty() ? nullptr : &g;
    return nullptr;
}

const RunGroup* StudyIndex::group(const std::string& problem, const std::string& algorithm) const {
    for (const auto& g : groups_)
        if (g.problem == problem && g.algorithm == algorithm)
            return &g;
    return nullptr;
}

std::vector<std::string> StudyIndex::algorithms_on(const std::string& problem) const {
    std::vector<std::string> out;
    for (const auto& a : algorithms_)
        if (find(problem, a) != nullptr)
            out.push_back(a);
    return out;
}

std::string StudyIndex::label(const std::string& algorithm) const {
    const auto it = labels_.find(algorithm);
    return it == labels_.end() ? algorithm : it->second;
}

std::string StudyIndex::full_spec(const std::string& algorithm) const {
    const auto it = full_specs_.find(algorithm);
    return it == full_specs_.end() ? algorithm : it->second;
}

bool StudyIndex::paired(const std::string& problem) const {
    const auto it = paired_.find(problem);
    return it != paired_.end() && it->second;
}

std::string run_name(const StudyIndex& index, const RunRecord& run) {
    return run.problem + ", " + index.label(run.algorithm) + ", run " + std::to_string(run.run_index);
}

std::string failed_runs_note(const StudyIndex& index) {
    const auto& failed = index.failed();
    if (failed.empty())
        return "";
    std::string message = failed.front()->message.empty() ? "no message" : failed.front()->message;
    constexpr std::size_t longest = 200; // a caption quotes the reason, not a whole dump
    if (message.size() > longest)
        message = message.substr(0, longest) + "...";
    return std::to_string(failed.size()) + (failed.size() == 1 ? " failed run" : " failed runs") +
           " left out of every statistic (first: " + run_name(index, *failed.front()) + ": " + message + ").";
}

std::string infinite_runs_note(const StudyIndex& index) {
    const std::size_t n = index.infinite_runs();
    if (n == 0)
        return "";
    const std::size_t negative = index.negative_infinite_runs();
    const std::string where = negative == 0 ? "+inf" : negative == n ? "-inf" : "+inf or -inf";
    return std::to_string(n) + (n == 1 ? " run" : " runs") + " ended at " + where +
           (negative == 0 ? ": the worst value in medians, quartiles and rank-based tests; a mean or std "
                            "over such a run is inf."
                          : ": ranked last (+inf) or first (-inf) in medians, quartiles and rank-based "
                            "tests; a mean or std over such a run is infinite (undefined where +inf and "
                            "-inf meet).");
}

std::string left_out_notes(const StudyIndex& index) {
    std::string out;
    for (const auto& note : {failed_runs_note(index), infinite_runs_note(index)})
        if (!note.empty())
            out += " " + note;
    return out;
}

} // namespace mhb
