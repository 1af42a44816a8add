#include "results/analysis/run_precision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "results/analysis/factorial_effects.hpp" // gap_response
#include "results/analysis/statistics.hpp"
#include "results/store/context_ini.hpp"
#include "results/store/study_index.hpp" // split_spec_text

namespace mhb {

namespace {

constexpr double infinite = std::numeric_limits<double>::infinity();

// The first n values of a sample without its failed runs (NaN).
std::vector<double> usable(const std::vector<double>& values, std::int64_t n) {
    std::vector<double> out;
    for (std::int64_t i = 0; i < n && i < static_cast<std::int64_t>(values.size()); ++i)
        if (!std::isnan(values[static_cast<std::size_t>(i)]))
            out.push_back(values[static_cast<std::size_t>(i)]);
    return out;
}

double standard_error_of_mean(const std::vector<double>& values) {
    if (values.size() < 2)
        return infinite;
    return standard_deviation(values) / std::sqrt(static_cast<double>(values.size()));
}

} // namespace

double compared_value(const RunRecord& run) {
    if (!run.ok)
        return std::numeric_limits<double>::quiet_NaN();
    return run.f_opt ? gap_response(run.best_f, *run.f_opt) : run.best_f;
}

std::string compared_scale(bool optimum_known) {
    return optimum_known ? "log10(f - f*)" : "f";
}

double standard_error(const std::vector<double>& values, const std::vector<double>* reference, bool paired,
                      std::int64_t n) {
    if (reference == nullptr)
        return standard_error_of_mean(usable(values, n));
    if (paired) {
        const std::int64_t both =
            std::min<std::int64_t>(n, static_cast<std::int64_t>(std::min(values.size(), reference->size())));
        const auto first = static_cast<std::size_t>(both);
        return standard_error_of_mean(
            paired_differences(std::span(values).first(first), std::span(*reference).first(first)));
    }
    const double a = standard_error_of_mean(usable(values, n));
    const double b = standard_error_of_mean(usable(*reference, n));
    return std::sqrt(a * a + b * b);
}

CellPrecision stopping_point(const std::vector<double>& values, const std::vector<double>* reference,
                             bool paired, const PrecisionRule& rule) {
    const auto available = [&](std::int64_t n) {
        return static_cast<std::int64_t>(values.size()) >= n &&
               (reference == nullptr || static_cast<std::int64_t>(reference->size()) >= n);
    };
    CellPrecision cell;
    cell.runs = std::min(rule.initial, rule.max);
    while (true) {
        if (!available(cell.runs)) {
            cell.stop = PrecisionStop::needs_runs;
            cell.standard_error = infinite;
            return cell;
        }
        cell.standard_error = standard_error(values, reference, paired, cell.runs);
        if (cell.standard_error <= rule.precision) {
            cell.stop = PrecisionStop::precision_reached;
            return cell;
        }
        if (cell.runs >= rule.max) {
            cell.stop = PrecisionStop::max_reached;
            return cell;
        }
        cell.runs = std::min(cell.runs + rule.step, rule.max);
    }
}

std::optional<PrecisionRule> precision_rule_of(std::string_view study_text) {
    PrecisionRule rule;
    bool by_precision = false;
    for (const auto& [key, value] : context_entries(study_text)) {
        if (key == "runs")
            by_precision = value == "auto";
        else if (key == "precision")
            rule.precision = std::stod(value);
        else if (key == "max-runs")
            rule.max = std::stoll(value);
        else if (key == "initial-runs")
            rule.initial = std::stoll(value);
        else if (key == "round-runs")
            rule.step = std::stoll(value);
    }
    if (!by_precision)
        return std::nullopt;
    return rule;
}

std::size_t default_reference_index(const std::vector<std::string>& algorithms) {
    for (std::size_t i = 0; i < algorithms.size(); ++i)
        if (algorithms[i] == "itlbo")
            return i;
    for (std::size_t i = 0; i < algorithms.size(); ++i)
        if (split_spec_text(algorithms[i]).name == "itlbo")
            return i;
    return 0;
}

} // namespace mhb
