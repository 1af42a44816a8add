// An evaluation budget that depends on the problem's dimension D, as the CEC competitions set
// theirs, in the words of a budget text (`budget = evaluations=...`):
//   evaluations=10000*dim                   10 000 x D evaluations (CEC 2017: MaxFES = 10000 D)
//   evaluations=dim10:200000+dim20:1000000  a count per dimension, for the dimensions listed only
//                                           (CEC 2022: 200 000 at D = 10, 1 000 000 at D = 20)
// The study keeps the text as its budget (one factor level, one report for every dimension, run
// identities that name the rule); each run gets the count of its problem's dimension.
//
// It lives in results/ because both sides read it: the runner resolves each run's budget, and the
// report the evaluation count of each problem (budget columns, CEC checkpoints) from the budget
// text that runs.csv records and the runs' dimension.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mhb {

// The most evaluations a budget may give a run, however it is written.
inline constexpr std::int64_t max_budget_evaluations = 1000000000000000LL;

struct DimensionEvaluations {
    std::int64_t per_dimension = 0;                            // N of N*dim; 0 for a list
    std::vector<std::pair<std::int64_t, std::int64_t>> listed; // (D, evaluations), D ascending

    // Whether an `evaluations=` value is meant as one of these forms rather than a plain count: it
    // holds '*', ':' or "dim". (A plain count keeps the plain count's checks and messages.)
    static bool written_in(std::string_view value);
    // Reads `value` (counts may be written 1e4). Throws std::invalid_argument naming the value, what
    // is wrong and the forms allowed, e.g. "budget: parameter 'evaluations' = 10000*D is not ...".
    static DimensionEvaluations parse(std::string_view value);

    // The canonical text: "10000*dim", "dim10:200000+dim20:1000000" (D ascending).
    [[nodiscard]] std::string text() const;
    // The evaluations at dimension D; empty when D is not listed. Throws std::invalid_argument when
    // N x D exceeds max_budget_evaluations.
    [[nodiscard]] std::optional<std::int64_t> at(std::int64_t dimension) const;
    // The dimensions a list names, "10, 20" (empty for N*dim), for messages.
    [[nodiscard]] std::string dimensions_text() const;
};

// The evaluations a budget text (e.g. "evaluations=10000*dim,target=1e-08") gives a problem of
// dimension D: its plain count, or its rule's count at D. Empty when the budget has no evaluation
// count, does not list D, or does not read.
std::optional<std::int64_t> budget_evaluations_at(std::string_view budget, std::int64_t dimension);

} // namespace mhb
