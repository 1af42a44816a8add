#include "runner/study/study_budget.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/core/spec.hpp"

namespace mhb {

std::string budget_text(const StudyBudget& budget) {
    std::string out;
    const auto add = [&out](const std::string& item) { out += (out.empty() ? "" : ",") + item; };
    if (budget.max_iterations)
        add("iterations=" + std::to_string(*budget.max_iterations));
    if (budget.max_evaluations)
        add("evaluations=" + std::to_string(*budget.max_evaluations));
    else if (budget.evaluations_by_dimension)
        add("evaluations=" + budget.evaluations_by_dimension->text());
    if (budget.target_error)
        add("target=" + format_real(*budget.target_error));
    if (budget.relative_target)
        add("relative_target=" + format_real(*budget.relative_target));
    return out;
}

StudyBudget parse_budget(std::string_view text) {
    static const std::vector<ParameterInfo> declared = {
        ParameterInfo::integer("iterations", 1, 1, 1000000000000000LL, "iterations after initialisation"),
        ParameterInfo::integer("evaluations", 1, 1, 1000000000000000LL, "function evaluations"),
        ParameterInfo::real("target", 0.0, 0.0, std::numeric_limits<double>::infinity(),
                            "stop once f - f* <= target"),
        ParameterInfo::real("relative_target", 0.0, 0.0, std::numeric_limits<double>::infinity(),
                            "stop once f - f* <= relative_target x |f*|")};
    Spec spec = Spec::parse("budget:" + std::string(text));
    StudyBudget budget;
    // Evaluations that depend on the dimension are read here; a plain count keeps the checks and
    // messages of any integer parameter.
    if (const std::string* evaluations = spec.find("evaluations");
        evaluations != nullptr && DimensionEvaluations::written_in(*evaluations)) {
        budget.evaluations_by_dimension = DimensionEvaluations::parse(*evaluations);
        std::erase_if(spec.parameters, [](const auto& kv) { return kv.first == "evaluations"; });
    }
    const ParameterValues values = validate_parameters("budget", declared, spec);
    if (values.given("iterations"))
        budget.max_iterations = values.integer("iterations");
    if (values.given("evaluations"))
        budget.max_evaluations = values.integer("evaluations");
    if (values.given("target"))
        budget.target_error = values.real("target");
    if (values.given("relative_target"))
        budget.relative_target = values.real("relative_target");
    if (budget.target_error && budget.relative_target)
        throw std::invalid_argument(
            "budget '" + std::string(text) +
            "': give target=E (f - f* <= E) or relative_target=R (f - f* <= R x |f*|), not both");
    if (!budget.max_iterations && !budget.max_evaluations && !budget.evaluations_by_dimension)
        throw std::invalid_argument(
            "budget '" + std::string(text) +
            "': give iterations=N and/or evaluations=N (target=E or relative_target=R is optional)");
    return budget;
}

std::optional<std::string> relative_target_refusal(std::optional<double> f_opt) {
    if (!f_opt)
        return "a relative target needs a known optimum";
    if (*f_opt == 0.0 || !std::isfinite(*f_opt))
        return "a relative target needs a finite, non-zero f* (it stops at f - f* <= relative_target x |f*|; "
               "give target=E instead)";
    return std::nullopt;
}

Budget StudyBudget::for_problem(std::int64_t dimension, std::optional<double> f_opt) const {
    Budget budget = *this;
    if (relative_target) {
        if (const auto refusal = relative_target_refusal(f_opt))
            throw std::invalid_argument("budget '" + budget_text(*this) + "': " + *refusal +
                                        (f_opt ? "; f* = " + format_real(*f_opt) : std::string()));
        budget.target_error = *relative_target * std::fabs(*f_opt);
    }
    if (evaluations_by_dimension) {
        const auto evaluations = evaluations_by_dimension->at(dimension);
        if (!evaluations)
            throw std::invalid_argument("budget '" + budget_text(*this) +
                                        "' gives no evaluations at dimension " + std::to_string(dimension) +
                                        "; it lists " + evaluations_by_dimension->dimensions_text());
        budget.max_evaluations = *evaluations;
    }
    return budget;
}

} // namespace mhb
