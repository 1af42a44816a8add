// A study's budgets: what one budget of a study is (a Budget whose evaluations may depend on the
// problem's dimension), and its text, which study files, study.ini, run records and run
// identities all carry, so that writing and reading it back must agree to the character.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "problems/objective.hpp"
#include "results/analysis/dimension_budget.hpp"

namespace mhb {

// A study's budget: a Budget whose evaluation count may depend on the problem's dimension, as the
// CEC protocols set theirs (`evaluations=10000*dim`, `evaluations=dim10:200000+dim20:1000000`:
// results/analysis/dimension_budget.hpp). It is one budget of the study (one report for all dimensions, its
// text in every run's record and identity); each run gets the count of its problem's dimension.
struct StudyBudget : Budget {
    StudyBudget() = default;
    // A plain budget is a study budget. Implicit, so that code and tests that build a Budget keep
    // working where a study takes one.
    StudyBudget(const Budget& budget) : Budget(budget) {} // NOLINT(google-explicit-constructor)

    // Set instead of max_evaluations: the evaluations by dimension.
    std::optional<DimensionEvaluations> evaluations_by_dimension;

    // The budget of a run on a problem of `dimension`. Throws std::invalid_argument when the
    // evaluations by dimension do not list it.
    [[nodiscard]] Budget for_dimension(std::int64_t dimension) const;
};

// A budget as text: "iterations=150", "evaluations=15050", "iterations=150,evaluations=20000",
// "evaluations=10000*dim", with ",target=1e-08" when a target is set. RunRecord::budget and study
// files use it.
std::string budget_text(const StudyBudget& budget);
// The inverse of budget_text (keys in any order; 1e5 is accepted, and evaluations that depend on
// the dimension: results/analysis/dimension_budget.hpp). Throws std::invalid_argument naming the key and
// what is allowed.
StudyBudget parse_budget(std::string_view text);

} // namespace mhb
