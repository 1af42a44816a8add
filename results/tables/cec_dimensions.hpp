// The errors of a study that follows a CEC protocol, as its tables read them: per dimension, per
// function and algorithm the errors after MaxFES, the trials as CEC 2022 ranks them and the marker
// against the reference; per function each algorithm's mean error and its rank. Internal to
// results/tables/ (cec_tables.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "results/analysis/cec_protocol.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/tables/cec_tables.hpp"

namespace mhb::tables {

// One algorithm on one function: its runs, their errors after MaxFES, its trials as CEC 2022 ranks
// them, and its marker against the reference ("" for the reference and where no test ran).
struct Cell {
    const RunGroup* group = nullptr;
    std::vector<double> errors; // in the order of group->runs
    std::vector<CecTrial> trials;
    std::string marker;
};

// One dimension: its functions (problems, by number) and each function's cells by algorithm spec.
struct Dimension {
    std::int64_t dimension = 0;
    std::vector<CecProblem> functions;
    std::vector<std::map<std::string, Cell>> cells;
};

// The study's CEC problems by dimension, in the order cec_problems() gives them, with the markers against
// `reference` at `alpha`.
std::vector<Dimension> by_dimension(const StudyIndex& index, const CecProtocol& protocol,
                                    const std::string& reference, double alpha);

// How the study departs from the protocol at this dimension, as a sentence ("" when it does not).
std::string deviation_note(const CecProtocol& protocol, const Dimension& d);

// Per function (row) each algorithm's (column) mean error, on the functions the protocol ranks
// (not CEC 2017's F2) where every algorithm has runs.
struct MeanErrors {
    std::vector<std::size_t> functions;     // indices into Dimension::functions
    std::vector<std::vector<double>> means; // [function][algorithm]
    std::size_t excluded = 0;               // functions of the protocol's excluded one (F2 of 2017)
    std::size_t incomplete = 0;             // functions on which some algorithm has no successful run
};

MeanErrors mean_errors(const StudyIndex& index, const CecProtocol& protocol, const Dimension& d);

// The rank (1 = lowest) of each algorithm's mean error on each function of `m`.
std::vector<std::vector<double>> mean_error_ranks(const MeanErrors& m);

} // namespace mhb::tables
