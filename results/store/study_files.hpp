// A study directory on disk: the files it holds (StudyFiles) and what each is for. How the runner
// writes one is study_writer.hpp, how reports read it back study_data.hpp.
//
//   study.ini        the study as run (written by the runner; re-runnable with --study-file)
//   context.ini      version, git commit, compiler, build type, threads, date (varies by machine)
//   store.bin        every finished run, keyed by its identity (see RunKey): appended as each run
//                    finishes, each record checksummed (store_block.hpp), synced to disk at a
//                    bounded interval (StoreSyncPolicy) and at the end, kept when the study is
//                    done, so an interrupted study resumes and a finished one grows (more runs,
//                    algorithms, problems, budgets) by computing only the runs it does not hold
//   runs.csv         one record per run of study.ini, sorted by run_id  } rendered from store.bin;
//   curves.csv       best-so-far per iteration (long format)          } identical for any thread
//   checkpoints.csv  best-so-far on the shared evaluation grid        } count, finished only by
//   trajectories.csv best x per iteration, for named parameters       } StudyWriter::finish()
//   improvements.csv every strict improvement of best-so-far f (event improvement) and the last
//                    evaluation (event last) of each run that recorded them; runs stored before
//                    improvements were recorded have no rows (the file itself is newer: a study
//                    without it is read with no improvements)
//   algorithms.csv   one row per algorithm of the study: its canonical spec, its display label
//                    and its full spec (every parameter, defaults included)
//   timings.csv      wall seconds per run (the one thing that varies between two runs)
//   .mhbench-study   the marker (study_marker.hpp); once finished, the study.ini and run count runs.csv was
//                    rendered for, and the size and CRC-32C of each rendered file (RenderedFile)
//
// A directory is a study when it holds .mhbench-study (or, from before that marker or having lost
// it, study.ini with runs.csv, store.bin or journal.txt); it is a finished study exactly when runs.csv
// exists, written last, by rename, and removed first whenever the study is changed. Studies written before
// store.bin (format 2: journal.txt keyed by run_id) are read, but not resumed or extended.
#pragma once

namespace mhb {

struct StudyFiles {
    static constexpr const char* study = "study.ini";
    static constexpr const char* context = "context.ini";
    static constexpr const char* runs = "runs.csv";
    static constexpr const char* curves = "curves.csv";
    static constexpr const char* checkpoints = "checkpoints.csv";
    static constexpr const char* trajectories = "trajectories.csv";
    static constexpr const char* improvements = "improvements.csv";
    static constexpr const char* timings = "timings.csv";
    static constexpr const char* algorithms = "algorithms.csv";
    // Marks a directory as a mhbench study, so that --out never takes over a directory of the
    // user's own files; its text names the format.
    static constexpr const char* marker = ".mhbench-study";
    // In a shard's directory (`mhbench run --shard i/n`): "shard = i/n".
    static constexpr const char* shard = "shard.txt";
    static constexpr const char* store = "store.bin";
    // Format 2 (before store.bin): the journal of an unfinished study, keyed by run_id.
    static constexpr const char* journal = "journal.txt";
    // Names the one process writing the directory, whose advisory lock is on the directory itself
    // (runner/execution/study_lock.hpp); not a record: present only while a writer holds the lock,
    // or after one was killed.
    static constexpr const char* lock = ".mhbench.lock";
};

} // namespace mhb
