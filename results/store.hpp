// A study directory on disk: how the runner writes it and how reports read it back.
//
//   study.ini        the study as run (written by the runner; re-runnable with --study-file)
//   context.ini      version, git commit, compiler, build type, threads, date (varies by machine)
//   runs.csv         one record per run, sorted by run_id          } identical for any thread
//   curves.csv       best-so-far per iteration (long format)        } count: finished only by
//   checkpoints.csv  best-so-far on the shared evaluation grid      } StudyWriter::finish()
//   trajectories.csv best x per iteration, for named parameters     }
//   algorithms.csv   one row per algorithm of the study: its canonical spec, its display label
//                    and its full spec (every parameter, defaults included)
//   timings.csv      wall seconds per run (the one thing that varies between two runs)
//   journal.txt      while a study runs: every finished run, appended and flushed at once, so
//                    an interrupted study resumes without losing or repeating a run
//
// A directory is a study when it holds .mhbench-study (or, from before that marker, study.ini
// with runs.csv or journal.txt); it is a finished study exactly when runs.csv exists, written
// last, by rename.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "results/run_record.hpp"

namespace mhb {

struct StudyFiles {
    static constexpr const char* study = "study.ini";
    static constexpr const char* context = "context.ini";
    static constexpr const char* runs = "runs.csv";
    static constexpr const char* curves = "curves.csv";
    static constexpr const char* checkpoints = "checkpoints.csv";
    static constexpr const char* trajectories = "trajectories.csv";
    static constexpr const char* timings = "timings.csv";
    static constexpr const char* algorithms = "algorithms.csv";
    // Marks a directory as a mhbench study, so that --out never takes over a directory of the
    // user's own files; its text names the format.
    static constexpr const char* marker = ".mhbench-study";
    // In a shard's directory (`mhbench run --shard i/n`): "shard = i/n".
    static constexpr const char* shard = "shard.txt";
    static constexpr const char* journal = "journal.txt";
};

// An algorithm of the study as the report shows it (algorithms.csv).
struct AlgorithmInfo {
    std::string spec;      // canonical: defaults dropped, values normalised, as in RunRecord::algorithm
    std::string label;     // display name: `label=` of the spec, a grid label such as itlbo[T-S+O-], or spec
    std::string full_spec; // every declared parameter with its value, e.g. tlbo:np=50,r=coordinate
};

class StudyWriter {
public:
    // Prepares `dir` for a study described by `study_text` (the content of study.ini).
    // - If `dir` holds an unfinished run of the same study, its finished runs are kept
    //   (completed() lists them) and the study resumes.
    // - If it holds a finished study, or an unfinished one of another study, this throws
    //   std::runtime_error unless `overwrite` is set, in which case those files are replaced.
    // - If it holds anything but a study (a user's own files), this throws, overwrite or not.
    // `parameter_columns` is the union of the named parameters of the study's problems, in order:
    // runs.csv gets the columns P, P_true, P_opt and P_err_pct for each (P_opt: the coordinate of
    // the known optimum, e.g. the least-squares estimate; P_err_pct: 100 (P - P_true) / P_true).
    // `algorithms` (in study order) becomes algorithms.csv; none: no such file.
    StudyWriter(std::filesystem::path dir, std::string study_text, std::string context_text,
                std::vector<std::string> parameter_columns, bool overwrite,
                const std::vector<AlgorithmInfo>& algorithms = {});

    [[nodiscard]] const std::set<std::int64_t>& completed() const { return completed_; }
    [[nodiscard]] const std::filesystem::path& directory() const { return dir_; }

    // Journals one finished run (thread-safe; the block is written and flushed in one go).
    void append(const RunRecord& record, double wall_seconds);

    // Writes the sorted result files, runs.csv last, and removes the journal.
    void finish();

private:
    struct Block {
        std::string run_line;
        std::string curve_lines;
        std::string checkpoint_lines;
        std::string trajectory_lines;
        std::string timing_line;
    };
    [[nodiscard]] Block render(const RunRecord& record, double wall_seconds) const;
    void load_journal();

    std::filesystem::path dir_;
    std::vector<std::string> parameter_columns_;
    std::mutex mutex_;
    std::map<std::int64_t, Block> blocks_;
    std::set<std::int64_t> completed_;
};

// True when `dir` is a mhbench study directory (see above).
bool is_study_directory(const std::filesystem::path& dir);

// The header of runs.csv for the given parameter columns.
std::string runs_csv_header(const std::vector<std::string>& parameter_columns);

struct StudyData {
    std::filesystem::path directory;
    std::string study_text;
    std::string context_text;
    std::vector<std::string> parameter_columns;
    // In study order; empty for studies written before algorithms.csv existed (then label and
    // full spec are the spec itself).
    std::vector<AlgorithmInfo> algorithms;
    std::vector<RunRecord> runs; // sorted by run_id, with curve and checkpoints filled in
    std::map<std::int64_t, double> wall_seconds;
};

// Reads a finished study directory. Throws std::runtime_error naming the file (and line) when
// a file is missing, truncated or malformed, or when the directory holds an unfinished study.
StudyData load_study(const std::filesystem::path& dir);

} // namespace mhb
