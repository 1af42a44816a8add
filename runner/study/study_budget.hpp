// A study's budgets: what one budget of a study is (a Budget whose evaluations may depend on the
// problem's dimension, and whose target may be relative to the problem's f*), and its text, which study
// files, study.ini, run records and run identities all carry, so that writing and reading it back must agree
// to the character.
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
    // Set instead of target_error: stop once f - f* <= relative_target x |f*|, a target that means
    // the same on problems whose f* differ by orders of magnitude (a least-squares fit in A^2 and
    // one in V^2). Each run's target_error is resolved from its problem's f* (for_problem).
    std::optional<double> relative_target;

    // The budget of a run on a problem of `dimension` whose known optimum is `f_opt`: its
    // evaluation count, and its target_error (relative_target x |f*| for a relative target).
    // Throws std::invalid_argument when the evaluations by dimension do not list the dimension, or
    // a relative target has no finite, non-zero f* to be relative to (prepare_study says both
    // first, naming the problem).
    [[nodiscard]] Budget for_problem(std::int64_t dimension, std::optional<double> f_opt) const;
};

// A budget as text: "iterations=150", "evaluations=15050", "iterations=150,evaluations=20000",
// "evaluations=10000*dim", with ",target=1e-08" or ",relative_target=1e-06" when a target is set.
// RunRecord::budget and study files use it.
std::string budget_text(const StudyBudget& budget);
// The inverse of budget_text (keys in any order; 1e5 is accepted, and evaluations that depend on
// the dimension: results/analysis/dimension_budget.hpp). Throws std::invalid_argument naming the key and
// what is allowed, and when both target and relative_target are given.
StudyBudget parse_budget(std::string_view text);
// Why a relative target cannot be resolved against a problem whose known optimum is `f_opt` (none,
// zero or not finite: f - f* <= R x |f*| would then ask for f* exactly, or mean nothing); empty when
// it can.
std::optional<std::string> relative_target_refusal(std::optional<double> f_opt);

} // namespace mhb
