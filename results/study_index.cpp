#include "results/study_index.hpp"

#include <algorithm>
#include <charconv>

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

std::vector<double> RunGroup::final_values() const {
    std::vector<double> values;
    values.reserve(runs.size());
    for (const auto* r : runs)
        values.push_back(r->best_f);
    return values;
}

StudyIndex::StudyIndex(const StudyData& data) {
    const auto remember = [](std::vector<std::string>& list, const std::string& name) {
        if (std::find(list.begin(), list.end(), name) == list.end())
            list.push_back(name);
    };
    for (const auto& r : data.runs) {
        remember(problems_, r.problem);
        remember(algorithms_, r.algorithm);
    }
    for (const auto& p : problems_)
        for (const auto& a : algorithms_) {
            RunGroup group;
            group.problem = p;
            group.algorithm = a;
            for (const auto& r : data.runs) {
                if (r.problem != p || r.algorithm != a)
                    continue;
                if (r.ok)
                    group.runs.push_back(&r);
                else
                    ++group.failed;
            }
            failed_ += group.failed;
            std::stable_sort(
                group.runs.begin(), group.runs.end(),
                [](const RunRecord* x, const RunRecord* y) { return x->run_index < y->run_index; });
            if (!group.runs.empty() || group.failed > 0)
                groups_.push_back(std::move(group));
        }
}

const RunGroup* StudyIndex::find(const std::string& problem, const std::string& algorithm) const {
    for (const auto& g : groups_)
        if (g.problem == problem && g.algorithm == algorithm)
            return g.runs.empty() ? nullptr : &g;
    return nullptr;
}

std::vector<std::string> StudyIndex::algorithms_on(const std::string& problem) const {
    std::vector<std::string> out;
    for (const auto& a : algorithms_)
        if (find(problem, a) != nullptr)
            out.push_back(a);
    return out;
}

} // namespace mhb
