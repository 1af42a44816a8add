// The algorithms and problems of a prepared study (runner/study/study.hpp), each with everything
// prepare_study() learnt about it in one place: one struct per component rather than one vector
// per fact, so that a component's spec, version, module and built object cannot drift apart.
#pragma once

#include <memory>
#include <string>

#include "algorithms/optimizer.hpp"
#include "problems/problem.hpp"
#include "results/store/algorithm_info.hpp"

namespace mhb {

// One optimiser of a study, built once and shared read-only by all its runs.
struct PreparedAlgorithm {
    // Its canonical spec (Registry::minimal), label and full spec: what algorithms.csv stores.
    AlgorithmInfo info;
    // The implementation version (Registry Entry::version). Version 1 adds no fact to a run's
    // identity (run_identity.cpp).
    int version = 1;
    // The plug-in module that provides it (path and SHA-256), both empty for a built-in one: the
    // module's hash joins the identity of every run it made.
    DataFile module{};
    std::unique_ptr<Optimizer> optimizer{};
};

// One problem of a study, built once and shared read-only by all its runs.
struct PreparedProblem {
    std::string spec; // canonical (Registry::normalised), ranges expanded
    // The same with each data file named by its SHA-256 instead of its path: what the problem's
    // runs depend on (seeds and run identities use it, so moving a file changes nothing and
    // editing one is noticed).
    std::string identity;
    int version = 1;   // as PreparedAlgorithm::version
    DataFile module{}; // as PreparedAlgorithm::module
    std::unique_ptr<Problem> problem{};
};

} // namespace mhb
