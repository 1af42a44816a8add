// The target of a budget, read from its text as runs.csv records it: `target=1e-08` (a run
// succeeds once f - f* <= 1e-08) or `relative_target=1e-06` (once f - f* <= 1e-06 x |f*|), for the
// captions that say what success meant. The runner writes the text (runner/study/study_budget.hpp);
// results/ depends on no other library, so it reads the two keys here.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace mhb {

struct BudgetTarget {
    std::string value; // as the budget text writes it, e.g. "1e-06"
    bool relative = false;

    // "f - f* <= 1e-08", or "f - f* <= 1e-06 x |f*|, a relative target".
    [[nodiscard]] std::string condition() const;
};

// Empty when the budget text sets no target.
std::optional<BudgetTarget> budget_target(std::string_view budget);

} // namespace mhb
