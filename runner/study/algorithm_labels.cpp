#include "runner/study/algorithm_labels.hpp"

#include <algorithm>
#include <cctype>

#include "problems/core/parameters.hpp"

namespace mhb {

std::string grid_label(const AlgorithmRegistry::Entry& entry,
                       const std::vector<std::pair<std::string, std::string>>& varying) {
    std::vector<std::pair<std::string, std::string>> switches; // key, normal value
    std::vector<std::string> others;
    for (const auto& [key, value] : varying) {
        const ParameterInfo& p = AlgorithmRegistry::declaration(entry, key);
        if (p.kind == ParameterKind::boolean)
            switches.emplace_back(key, normal_value(p, value));
        else
            others.push_back(key + "=" + normal_value(p, value));
    }
    // One capital letter per switch while the letters tell them apart; the whole key otherwise.
    bool letters_unique = true;
    for (std::size_t i = 0; i < switches.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            letters_unique = letters_unique && switches[i].first[0] != switches[j].first[0];
    std::string inside;
    for (const auto& [key, value] : switches) {
        const std::string sign = value == "on" ? "+" : "-";
        if (letters_unique)
            inside += static_cast<char>(std::toupper(static_cast<unsigned char>(key[0]))) + sign;
        else
            inside += (inside.empty() ? "" : ",") + key + sign;
    }
    for (const auto& o : others)
        inside += (inside.empty() ? "" : ",") + o;
    return entry.name + "[" + inside + "]";
}

std::string short_label(const AlgorithmRegistry& registry, const Spec& spec) {
    const AlgorithmRegistry::Entry& entry = registry.find(spec.name);
    const Spec minimal = registry.minimal(spec);
    const DisplayName& display = entry.display;
    if (display.name.empty() && display.parameter.empty())
        return minimal.canonical();
    std::string name = display.name.empty() ? entry.name : display.name;
    std::vector<std::string> suffix;
    if (!display.parameter.empty()) {
        const Spec full = registry.full(spec);
        const std::string* value = full.find(display.parameter);
        const auto named = std::find_if(display.by_value.begin(), display.by_value.end(),
                                        [&](const auto& v) { return value != nullptr && v.first == *value; });
        if (named != display.by_value.end())
            name = named->second;
        else if (value != nullptr) // a value without a name of its own: said like any other
            suffix.push_back(display.parameter + "=" + *value);
    }
    for (const auto& [key, value] : minimal.parameters)
        if (key != display.parameter)
            suffix.push_back(key + "=" + value);
    if (suffix.empty())
        return name;
    std::string joined;
    for (const auto& s : suffix)
        joined += (joined.empty() ? "" : ", ") + s;
    // "CMA-ES (BIPOP)" with lambda=20 is "CMA-ES (BIPOP, lambda=20)", not two parentheses.
    if (name.back() == ')')
        return name.substr(0, name.size() - 1) + ", " + joined + ")";
    return name + " (" + joined + ")";
}

std::map<std::string, std::string> unique_short_labels(const std::map<std::string, std::string>& wanted,
                                                       const std::vector<std::string>& taken) {
    std::map<std::string, int> uses;
    for (const auto& [spec, label] : wanted)
        ++uses[label];
    std::map<std::string, std::string> out;
    for (const auto& [spec, label] : wanted) {
        const bool clash = uses[label] > 1 || std::find(taken.begin(), taken.end(), label) != taken.end();
        out[spec] = clash ? spec : label;
    }
    return out;
}

} // namespace mhb
