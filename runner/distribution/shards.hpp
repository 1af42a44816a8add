// Job arrays: a study split into n shards that run anywhere, in any order, and merge into the
// directory one process would have written (records byte for byte).
//
// The split must come out the same on every machine that computes it, since each shard computes
// its own part: it is balanced by a deterministic cost estimate, never by timing. A run's cost is
// its estimated evaluations (exact for evaluation budgets; for iteration budgets, the evaluations
// of a 3-iteration calibration run extrapolated, which is deterministic like any run) times the
// problem's dimension (an evaluation's cost grows with it). Runs are dealt largest first to the
// least-loaded shard (ties: lower run id, lower shard), so the shards' totals differ by at most
// the largest single run.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "runner/study/study.hpp"

namespace mhb {

struct ShardSpec {
    int index = 1; // 1-based
    int count = 1;
};

// "i/n" with 1 <= i <= n <= 100000; std::invalid_argument naming the text otherwise.
ShardSpec parse_shard(std::string_view text);
std::string shard_text(const ShardSpec& shard); // "i/n"

// The run ids of every shard (index 0 is shard 1/n), each sorted.
std::vector<std::vector<std::int64_t>> shard_run_ids(const PreparedStudy& study, int count);

// The estimated cost of every run of the study, in the units above.
std::vector<double> estimated_run_costs(const PreparedStudy& study);

} // namespace mhb
