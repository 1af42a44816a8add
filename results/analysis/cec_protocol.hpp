// The CEC competitions' protocols as numbers: what the organisers ask to be recorded of every run
// and how they rank entries. A study follows one by name (`protocol = cec2017` in its study file)
// through results/protocols/, which makes each of these a protocol component.
//
//   CEC 2017 (Awad, Ali, Liang, Qu, Suganthan, "Problem definitions and evaluation criteria for the
//   CEC 2017 special session and competition on single objective real-parameter numerical
//   optimization", section 2): 51 runs, MaxFES = 10000 D, the error f - f* recorded after
//   (0.01, 0.02, 0.03, 0.05, 0.1, 0.2, ..., 0.9, 1.0) x MaxFES evaluations (14 values per run);
//   an error below 1e-8 is taken as 0; one file per algorithm, function and dimension,
//   "AlgorithmName_F_D.txt", a 14 x 51 matrix (a row per checkpoint, a column per run).
//   CEC 2022 (Kumar, Price, Mohamed, Hadi, Suganthan, TR of the CEC 2022 competition, section 2):
//   30 runs, MaxFES = 200 000 at D = 10 and 1 000 000 at D = 20, the error after
//   floor(D^(k/5 - 3) MaxFES) evaluations for k = 0..15, and a 17th row FEterm: the evaluation at
//   which the error first fell below 1e-8 (MaxFES for a run that never did). The TR's text asks for
//   1e-8 in the entries after such a run terminates; its official example code (lshade.cpp) sets an
//   error below 1e-8 to 0, as CEC 2017 does: mhbench writes 0 for both, which ranks the same.
//
// Errors are exact at every checkpoint: best-so-far comes from the run's recorded improvements
// (RunRecord::improvements, every strict improvement at the evaluation that made it), so nothing
// is recorded for the protocol while the optimiser runs.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "results/store/run_record.hpp" // a run's record: every room reads it

namespace mhb {

// Errors below this are taken as 0 (both protocols).
inline constexpr double cec_error_threshold = 1e-8;

struct CecProtocol {
    std::string_view name;   // as `protocol =` writes it: "cec2017"
    std::string_view title;  // "CEC 2017"
    std::string_view family; // the problem family of its suite: "cec2017"
    int runs = 0;            // per function and dimension
    // The protocol's MaxFES as an evaluations= value (results/analysis/dimension_budget.hpp).
    std::string_view evaluations;
    // CEC 2022: a last row FEterm after the checkpoints' errors.
    bool termination_row = false;
    // A function of the suite the organisers left out of the competition (CEC 2017's F2, defined in
    // the code but dropped from the final definitions): reported, but not ranked or scored. 0: none.
    int excluded_function = 0;

    // The evaluation counts whose errors a run records, ascending, for a problem of dimension D
    // whose budget is `max_fes` evaluations; the last is max_fes. None is below 1 (a budget far
    // below the protocol's could floor the first to 0 evaluations, where no error exists yet).
    [[nodiscard]] std::vector<std::int64_t> checkpoints(std::int64_t max_fes, std::int64_t dimension) const;
    // How each row of a result file is described, "0.01 x MaxFES" or "floor(D^(-3) MaxFES)" ...
    [[nodiscard]] std::vector<std::string> row_names() const;
};

// Every competition's rules, in order (results/protocols/ makes each a protocol a study names).
std::span<const CecProtocol> cec_protocols();
// nullptr for a name that is not a competition's.
const CecProtocol* find_cec_protocol(std::string_view name);
// "cec2017, cec2022" (a message names the protocols a study may name: protocol_names()).
std::string cec_protocol_names();

// The protocol a study follows: the value of the `protocol = NAME` line of its study.ini, if any.
std::optional<std::string> study_protocol(std::string_view study_text);

// f - f* with an error below cec_error_threshold (or negative, by rounding) taken as 0.
double cec_error(double f, double f_opt);

// The error of a successful run after `evaluations` evaluations: best-so-far then (its final value
// when it stopped earlier; its exact improvements, else its curve and checkpoints for runs stored
// before improvements were recorded) minus f*, with the 1e-8 rule. NaN without f* or a value.
double cec_error_at(const RunRecord& run, std::int64_t evaluations);

// CEC 2022's FEterm: the evaluation at which the run's error first fell below 1e-8, else max_fes.
std::int64_t cec_termination_evaluations(const RunRecord& run, std::int64_t max_fes);

// The function number and dimension of a problem of a CEC family as runs.csv names it
// ("cec2017:dim=30,f=5"), with the family's defaults (f = 1; D from `dimension` otherwise, the
// runs' own); empty when it is not of `family`.
struct CecFunction {
    int number = 0;
    std::int64_t dimension = 0;
};
std::optional<CecFunction> cec_function(const std::string& problem, std::string_view family,
                                        std::int64_t dimension);

class StudyIndex;
// A problem of a protocol study as the protocol sees it.
struct CecProblem {
    std::string problem; // its spec, as runs.csv names it
    int function = 0;
    std::int64_t dimension = 0;
    // MaxFES: the budget's evaluations at this dimension, else (the budget has none) the most any
    // run on the problem spent.
    std::int64_t max_fes = 0;
    bool max_fes_from_budget = true;
};
// The problems of `index` from the protocol's family, by dimension, then function number.
std::vector<CecProblem> cec_problems(const StudyIndex& index, const CecProtocol& protocol);

} // namespace mhb
