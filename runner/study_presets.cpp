#include "runner/study_presets.hpp"

#include <stdexcept>

namespace mhb {
namespace {

Study make_study(std::vector<std::string> algorithms, std::vector<std::string> problems, std::int64_t runs,
                 std::int64_t iterations) {
    Study s;
    s.algorithms = std::move(algorithms);
    s.problems = std::move(problems);
    s.runs = runs;
    s.budget.max_iterations = iterations;
    return s;
}

} // namespace

const std::vector<StudyPreset>& study_presets() {
    static const std::vector<StudyPreset> presets = {
        // Li, Wang and Ji (2017), section 4: NP = 50 (each algorithm's default), 150 iterations,
        // 20 runs, the 2500 rpm / 2 N.m operating point.
        {"paper", "the paper's study: ITLBO, TLBO, PSO on PMSM at 2500 rpm, 2 N.m; 150 iterations, 20 runs",
         make_study({"itlbo", "tlbo", "pso"}, {"pmsm:speed=2500,load=2"}, 20, 150)},
        // Small enough to finish in a blink: checks an installation and the runner end to end.
        {"smoke", "a quick check: random search on a 5-D sphere; 100 iterations, 10 runs",
         make_study({"random-search"}, {"sphere:dim=5"}, 10, 100)},
    };
    return presets;
}

const StudyPreset& find_study_preset(std::string_view name) {
    std::string known;
    for (const auto& p : study_presets()) {
        if (p.name == name)
            return p;
        known += (known.empty() ? "" : ", ") + p.name;
    }
    throw std::invalid_argument("unknown study '" + std::string(name) + "'; known: " + known);
}

} // namespace mhb
