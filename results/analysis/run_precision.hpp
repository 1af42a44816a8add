// Runs by precision (`runs = auto`): how many runs a cell (an algorithm on a problem at a budget)
// needs before the difference to the reference is known well enough, after Campelo & Takahashi
// ("Sample size estimation for power and accuracy in the experimental comparison of algorithms",
// J. Heuristics 25, 2019), simplified to rounds so that the same records always give the same
// stopping points.
//
// The rule, one cell at a time: start with `initial` runs; after each round, compute the standard
// error of the mean difference to the reference on the compared scale (compared_value); stop when
// it is at most `precision`, or when the cell has `max` runs; otherwise add `step` runs (never
// beyond `max`). The difference is paired by run index under common random numbers (run r of both
// starts from one stream: SE = sd(d) / sqrt(n)), Welch's otherwise (sqrt(s_a^2 / n + s_ref^2 / n));
// the reference's own cell, and a study of one algorithm, use the standard error of its mean.
// A cell's stopping point depends on its own runs and the reference's first runs only, so the order
// in which rounds run, the thread count and an interruption change nothing.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "results/store/run_record.hpp"

namespace mhb {

struct PrecisionRule {
    double precision = 0.0; // largest standard error accepted, on the compared scale
    std::int64_t initial = 10;
    std::int64_t step = 5;
    std::int64_t max = 100;
};

// The value a run is compared by: log10(max(f - f*, floor)) where f* is known (the factorial
// effects' scale, results/analysis/factorial_effects.hpp), f itself otherwise; NaN for a failed run.
double compared_value(const RunRecord& run);
// "log10(f - f*)" or "f".
std::string compared_scale(bool optimum_known);

// Standard error of the mean difference between the first n values of `values` and of `reference`
// (paired or Welch), or of the mean of `values` alone when `reference` is null. Failed runs (NaN)
// are left out, with their partner when paired; two equal infinities are a zero difference. +inf
// when fewer than two values remain or a difference is infinite.
double standard_error(const std::vector<double>& values, const std::vector<double>* reference, bool paired,
                      std::int64_t n);

enum class PrecisionStop {
    precision_reached, // the standard error fell to the precision
    max_reached,       // the cell got `max` runs first
    needs_runs,        // the rule wants runs that are not there yet
};

struct CellPrecision {
    std::int64_t runs = 0; // what the cell needs so far (its stopping point when stopped)
    double standard_error = 0;
    PrecisionStop stop = PrecisionStop::needs_runs;
};

// Where the rule stops on the cell whose compared values, by run index, are `values` (the
// reference's `reference`, or null), given the runs there are. Both vectors may be shorter than the
// rule needs: then stop = needs_runs and runs is the count it asks for.
CellPrecision stopping_point(const std::vector<double>& values, const std::vector<double>* reference,
                             bool paired, const PrecisionRule& rule);

// The rule a study file states (`runs = auto` with `precision`, `max-runs`, `initial-runs`,
// `round-runs`), from study.ini's text; none for a fixed number of runs.
std::optional<PrecisionRule> precision_rule_of(std::string_view study_text);

// The algorithm runs are compared with when none is named: `itlbo` (all defaults) if the study has
// it, else its first ITLBO variant, else its first algorithm. `algorithms`: canonical specs, in
// study order; not empty.
std::size_t default_reference_index(const std::vector<std::string>& algorithms);

} // namespace mhb
