// The competition's tables of a study that follows a CEC protocol (results/analysis/cec_protocol.hpp), for
// each dimension D of its problems, all from the errors after MaxFES (an error below 1e-8 is 0):
//  - "cec_errors_d<D>": per function and algorithm the best, worst, median, mean and std of the
//    error over the runs (the TRs' results template), and a marker against the reference from a
//    rank test of the errors (signed-rank where the runs pair by seed, rank-sum otherwise; Holm
//    across the function's comparisons), with a w/t/l row per algorithm under the table;
//  - "cec_ranks_d<D>": per algorithm the mean rank of its mean error over the functions (CEC 2017's
//    rank criterion: per function, rank 1 to the lowest mean error, ties averaged) with the Friedman
//    test of those ranks, its w/t/l against the reference and, for CEC 2022, its U-score (TR section
//    2.3: the trials of every algorithm on a function ranked together, those that reached 1e-8 by
//    FEterm ahead of the others by error, the best trial ranked highest; an algorithm's score is the
//    sum of its trials' ranks minus n(n + 1)/2, summed over the functions).
//  - "cec2017_score" (CEC 2017 with D = 10, 30, 50 and 100 all present): the competition's score
//    (TR section 2.3), Score1 = 50 SE_min / SE from the sums of mean errors and Score2 = 50 SR_min /
//    SR from the sums of their ranks, each summed over the functions and weighted 0.1, 0.2, 0.3, 0.4
//    by dimension; Score = Score1 + Score2 (100 for the best at both).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "results/analysis/cec_protocol.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

// Every table above; `reference` is an algorithm spec of the index.
std::vector<Table> cec_tables(const StudyIndex& index, const CecProtocol& protocol,
                              const std::string& reference, double alpha);

// One trial as CEC 2022's ranking sees it: whether it reached an error below 1e-8, at which
// evaluation (FEterm), and its error after MaxFES.
struct CecTrial {
    bool reached = false;
    std::int64_t termination = 0;
    double error = 0.0;
};

// The U-score of each algorithm on one function (TR 2022, section 2.3): `trials[j]` are algorithm
// j's trials. Ties share the mean of their ranks.
std::vector<double> cec_u_scores(const std::vector<std::vector<CecTrial>>& trials);

} // namespace mhb
