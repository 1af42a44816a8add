// Time per evaluation, from the wall time of each run (timings.csv, StudyData::wall_seconds):
// COCO's timing experiment (the "CPU timing" of its papers) reads the total time of a run divided
// by its evaluations, on the sphere at growing dimension, as an optimiser's cost per evaluation.
// That total includes the evaluation itself and the Objective's bookkeeping; an optimiser that
// does almost nothing (random-search) shows that floor, so the rows of the others read as their
// overhead above it.
//
// Wall times vary between machines and between two runs of a study; they are kept apart from the
// records for that reason (run_record.hpp), and so is this analysis: nothing else in a report
// depends on them.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

struct EvaluationTime {
    std::string problem;
    std::string algorithm;
    std::int64_t dimension = 0;       // of the problem's runs (their best point), 0 when unknown
    std::size_t runs = 0;             // successful runs with a wall time and at least one evaluation
    double median_microseconds = 0.0; // median over those runs of 1e6 x wall seconds / evaluations
    double total_seconds = 0.0;       // their wall seconds, summed
};

// Per (problem, algorithm) in study order, for the groups with at least one timed run. Empty when
// the study has no timings.
std::vector<EvaluationTime> evaluation_times(const StudyIndex& index,
                                             const std::map<std::int64_t, double>& wall_seconds);

} // namespace mhb
