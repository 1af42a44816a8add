// The helpers the paper's tables share (paper_common.hpp).
#include "results/tables/paper_common.hpp"

#include <algorithm>
#include <cstdlib>

#include "results/store/csv.hpp" // CSV as the store writes it, for every room

namespace mhb::tables {

namespace {

template <typename Entry>
const Entry* published_entry(const std::vector<Entry>& entries, const std::string& algorithm) {
    for (const auto& e : entries)
        if (e.algorithm == algorithm)
            return &e;
    return nullptr;
}

} // namespace

const PublishedFitness* published_fitness(const PmsmProblem& p, const std::string& algorithm) {
    return p.published == nullptr ? nullptr : published_entry(p.published->fitness, algorithm);
}

const PublishedIdentification* published_identification(const PmsmProblem& p, const std::string& algorithm) {
    return p.published == nullptr ? nullptr : published_entry(p.published->identification, algorithm);
}

int paper_parameter(const std::string& name) {
    for (std::size_t k = 0; k < pmsm_parameter_names.size(); ++k)
        if (pmsm_parameter_names[k] == name)
            return static_cast<int>(k);
    return -1;
}

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

std::string pmsm_problem_name(const std::string& spec) {
    const SpecText text = split_spec_text(spec);
    const auto value = [&](const std::string& key) {
        const auto at = text.parameters.find(key);
        return at == text.parameters.end() ? std::string() : at->second;
    };
    std::string name = "PMSM";
    if (const std::string data = value("data"); !data.empty()) {
        std::string files;
        for (std::size_t start = 0; start <= data.size();) {
            const std::size_t end = std::min(data.find('+', start), data.size());
            const std::string path = data.substr(start, end - start);
            files += (files.empty() ? " " : ", ") + path.substr(path.find_last_of('/') + 1);
            start = end + 1;
        }
        name += ", logged data" + files;
    } else if (const std::string conditions = value("conditions"); !conditions.empty()) {
        name += ", conditions " + conditions;
    } else {
        // A condition left at its default is not said: the defaults are the problem's to declare.
        if (const std::string speed = value("speed"); !speed.empty())
            name += ", " + speed + " rpm";
        if (const std::string load = value("load"); !load.empty())
            name += ", " + load + " N m";
    }
    if (const std::string model = value("model"); !model.empty() && model != "steady")
        name += ", " + std::string(model == "output" ? "output-error" : model) + " model";
    if (const std::string motor = value("motor"); !motor.empty() && motor != "paper")
        name += ", " + motor + " motor";
    if (!value("noise_i").empty() || !value("noise_u").empty())
        name += ", noisy";
    return name;
}

std::string paper_source(const PmsmProblem& p) {
    return std::string(paper_citation) + (p.published ? ", " + std::string(p.published->table) : "");
}

} // namespace mhb::tables
