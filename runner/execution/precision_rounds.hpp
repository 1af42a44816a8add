// Runs by precision (`runs = auto`, Study::by_precision): a study run in rounds. Each round runs
// what the rule of results/analysis/run_precision.hpp asks for, given every result known so far;
// the study ends when no cell asks for more. Which runs a round asks for is a function of the
// stored records alone (the plan is recomputed from them before each round), so the same command
// gives the same runs and stopping points whatever the thread count, and a study interrupted in
// the middle of a round resumes it.
//
// A study sharded for independent jobs cannot decide rounds (no shard sees the others' results):
// the CLI refuses the combination.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <vector>

#include "runner/execution/parallel_runner.hpp"
#include "runner/study/study.hpp"

namespace mhb {

// What the rule asks for, given the compared values (results/analysis/run_precision.hpp) of the
// runs finished so far, by run id.
struct PrecisionPlan {
    std::vector<std::int64_t> wanted; // every run the cells ask for so far, ascending
    std::int64_t unsettled_cells = 0; // cells that ask for runs not yet finished
};
PrecisionPlan plan_precision_runs(const PreparedStudy& study, const std::map<std::int64_t, double>& values);

struct PrecisionRoundStart {
    int round = 1;                    // counted in this session
    std::vector<std::int64_t> runs;   // to be done in the round
    std::int64_t unsettled_cells = 0; // the cells that asked for them
};

// Where the rounds run, and who hears of them: by default run_study in this process. Under MPI
// the CLI runs each round over every rank and tells the other ranks whether another follows
// (runner/distribution/distributed.hpp), since only rank 0 sees the results that decide it.
struct PrecisionRoundHooks {
    std::function<RunnerOutcome(const RunnerOptions& round)> run; // empty: run_study
    std::function<void(bool another_round)> announce;             // empty: nobody to tell
    std::function<void(const PrecisionRoundStart&)> on_round;     // before each round (progress)
};

// Runs `study` (which must have by_precision) in rounds into `writer`: options.run_ids is ignored,
// each round runs its own; on_run_finished is called as run_study calls it. When every cell has
// settled, the writer renders exactly the runs asked for; an interrupted study is left for a resume.
RunnerOutcome run_study_by_precision(const PreparedStudy& study, StudyWriter& writer,
                                     const RunnerOptions& options, const PrecisionRoundHooks& hooks = {});

} // namespace mhb
