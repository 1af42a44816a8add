#include "results/analysis/budget_target.hpp"

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

std::string BudgetTarget::condition() const {
    return relative ? "f - f* <= " + value + " x |f*|, a relative target" : "f - f* <= " + value;
}

std::optional<BudgetTarget> budget_target(std::string_view budget) {
    if (budget.empty())
        return std::nullopt;
    const SpecText spec = split_spec_text("budget:" + std::string(budget));
    if (const auto it = spec.parameters.find("relative_target"); it != spec.parameters.end())
        return BudgetTarget{it->second, true};
    if (const auto it = spec.parameters.find("target"); it != spec.parameters.end())
        return BudgetTarget{it->second, false};
    return std::nullopt;
}

} // namespace mhb
