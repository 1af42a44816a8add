// The specs of a prepared study's components as lists, for tests that compare them whole.
#pragma once

#include <string>
#include <vector>

#include "runner/study/study.hpp"

namespace mhb::test_support {

// The canonical spec of each algorithm, in run order.
inline std::vector<std::string> algorithm_specs(const PreparedStudy& prepared) {
    std::vector<std::string> specs;
    for (const PreparedAlgorithm& algorithm : prepared.algorithms)
        specs.push_back(algorithm.info.spec);
    return specs;
}

// The canonical spec of each problem, in run order.
inline std::vector<std::string> problem_specs(const PreparedStudy& prepared) {
    std::vector<std::string> specs;
    for (const PreparedProblem& problem : prepared.problems)
        specs.push_back(problem.spec);
    return specs;
}

} // namespace mhb::test_support
