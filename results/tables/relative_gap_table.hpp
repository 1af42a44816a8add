// The "relative_gaps" table (results/analysis/relative_gaps.hpp): algorithms as rows and, per
// problem with a known, non-zero f*, two columns: the median relative gap (f - f*) / |f*| of the
// final values and the success rate to the study's relative target. Problems whose f* differ by
// orders of magnitude read on one scale, so a reader sees on which problem the optimisers part.
#pragma once

#include "results/analysis/relative_gaps.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

Table relative_gap_table(const StudyIndex& index, const RelativeGaps& gaps);

} // namespace mhb
