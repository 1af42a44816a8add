// A run's identity in the study store: the SHA-256 of what determines its record — the canonical
// algorithm, the problem with each data file named by its content (not its path), the budget,
// the run index, the seed, the store's record format, and the implementation versions of the
// optimiser and the problem family from version 2 on (version 1 adds nothing, so that the runs
// stored before versions existed keep their identity). Two studies that share a run share its
// record, whatever they call it; extending a study computes only the runs it lacks.
//
// A run also has a slot (algorithm label, problem as written, budget, run index): what a user
// calls "the same run". A stored run in a wanted run's slot with another identity means something
// changed underneath (a data file edited, a labelled algorithm's parameter, the study seed, an
// implementation version), and describe_run_change() says what, in one line.
#pragma once

#include <cstdint>
#include <string>

#include "results/store/run_key.hpp"
#include "runner/study/study.hpp"

namespace mhb {

// The key of run `run_id` of `study`.
RunKey run_key(const PreparedStudy& study, std::int64_t run_id);

// Keys for every run of `study` (computed on demand; `study` must outlive the result).
StudyRunKeys study_run_keys(const PreparedStudy& study);

// One line naming what differs between a stored run and the wanted run of the same slot, e.g.
// "pmsm:data=drive.csv: the file changed since the study started (sha256 3f2a9c01.. -> 9b41d2e7..)".
std::string describe_run_change(const RunKey& stored, const RunKey& wanted);

} // namespace mhb
