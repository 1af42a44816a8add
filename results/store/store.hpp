// A study directory on disk: how the runner writes it and how reports read it back.
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
//   .mhbench-study   the marker (below); once finished, the study.ini and run count runs.csv was
//                    rendered for, and the size and CRC-32C of each rendered file (RenderedFile)
//
// A directory is a study when it holds .mhbench-study (or, from before that marker or having lost
// it, study.ini with runs.csv, store.bin or journal.txt); it is a finished study exactly when runs.csv
// exists, written last, by rename, and removed first whenever the study is changed. Studies written before
// store.bin (format 2: journal.txt keyed by run_id) are read, but not resumed or extended.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "results/store/run_record.hpp"

namespace mhb {

struct DecodedRecord;
class StoreReader; // internal to the study writer (study_writer_internal.hpp)

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

// The format of store.bin and of the records in it; part of every run's identity, so a change to
// what a record holds makes earlier stores refuse to be mixed with new runs. What is only added to
// a record (the improvement trace) is a section of it (record_codec.hpp) instead: the values of a
// stored run are still those this mhbench computes, so it stays usable, without the new section.
inline constexpr int store_format_version = 3;
// The framing of store.bin's blocks: format 4 adds a checksum to each (store_block.hpp); blocks
// of format 3 carry none and are still read. Not part of a run's identity: a checksum changes no
// value, so the runs of a format-3 store are reused as they are.
inline constexpr int store_block_format = 4;

// How often store.bin is synced to disk while runs are appended: after `runs` runs or `seconds`
// seconds, whichever comes first (checked as each run is stored), and always at the end. A crash
// of the machine loses at most the runs stored since the last sync (3 s of computing, or runs so
// cheap that 100 000 of them took less); the same command computes them again. A sync stalls the
// thread storing the run: every 10 000 runs, a study of 100 000 runs of 100 evaluations made 10 of
// them; every 3 s, it makes 1 or 2 (BENCHMARKS.md, "What durability costs").
struct StoreSyncPolicy {
    std::int64_t runs = 100000;
    double seconds = 3.0;
};

// What determines a run's record, and how a user names the run. The runner builds one per run of
// a study (runner/execution/run_identity.hpp); the store keeps it with the record.
struct RunKey {
    std::string identity; // SHA-256 (hex) of `facts`: the store's key
    // What a user calls "the same run": algorithm label, problem as written, budget, run index.
    // Two keys with one slot and different identities mean something changed under a stored run.
    std::string slot;
    std::string facts;     // "name = value" lines that determine the record (canonical specs, data
                           // file contents by SHA-256, budget, run index, seed, format version)
    std::string notes;     // "name = value" lines only for messages (data file paths)
    std::string algorithm; // canonical spec and problem as the study writes them in runs.csv
    std::string problem;
};

// The runs of the study being written, by run_id, and how to word a change under a stored run.
struct StudyRunKeys {
    std::int64_t count = 0;
    std::function<RunKey(std::int64_t run_id)> key;
    // The canonical algorithm and problem specs of a run (RunKey's), cheaper than key().
    std::function<std::pair<std::string, std::string>(std::int64_t run_id)> names;
    // One line saying what differs between a stored run and the wanted one of the same slot.
    std::function<std::string(const RunKey& stored, const RunKey& wanted)> describe_change;
    // Compute again the runs whose slot holds a stored run of another identity (a new
    // implementation version, an edited data file), instead of refusing; every other stored run
    // is kept, and the replaced ones stay in store.bin unused.
    bool recompute_changed = false;
    // The runs this directory is to hold, when not all `count` (a shard's); finish() renders
    // exactly these, and refuses when one is missing.
    std::optional<std::vector<std::int64_t>> run_ids;
};

// An algorithm of the study as the report shows it (algorithms.csv).
struct AlgorithmInfo {
    std::string spec;      // canonical: defaults dropped, values normalised, as in RunRecord::algorithm
    std::string label;     // display name: `label=` of the spec, a grid label such as itlbo[T-S+O-], or spec
    std::string full_spec; // every declared parameter with its value, e.g. tlbo:np=50,r=coordinate
};

// What finish() wrote, for a summary without reading the files back.
struct StudySummary {
    std::int64_t runs = 0;
    std::int64_t failed = 0;
    std::int64_t evaluations = 0;
    std::vector<RunRecord> first_failures; // up to three, without curves
};

class StudyWriter {
public:
    // Prepares `dir` for a study described by `study_text` (the content of study.ini).
    // - The runs in `dir`'s store.bin whose identity is a run of this study are kept
    //   (completed() lists their run_ids): the same study resumes, or re-renders when it was
    //   finished; a larger one (more runs, algorithms, problems, budgets) computes only the rest.
    // - A stored run with the slot of a wanted run but another identity (a data file, parameter
    //   or seed that changed) throws std::runtime_error with one line per change, unless
    //   `overwrite` is set, in which case the store is emptied and every run done again.
    // - A study of format 2 (journal.txt, or runs.csv without store.bin) throws unless
    //   `overwrite`; anything but a study (a user's own files) throws, overwrite or not.
    // - A stored record whose checksum fails, or that does not decode, is treated as missing: its
    //   run is computed again, and warnings() has one line naming it.
    // `parameter_columns` is the union of the named parameters of the study's problems, in order:
    // runs.csv gets the columns P, P_true, P_opt and P_err_pct for each (P_opt: the coordinate of
    // the known optimum, e.g. the least-squares estimate; P_err_pct: 100 (P - P_true) / P_true).
    // `algorithms` (in study order) becomes algorithms.csv; none: no such file.
    // Without `keys`, a run's identity is its run_id within this study text (tests, and tools that
    // write records directly): such a study resumes, but does not share runs with another.
    StudyWriter(std::filesystem::path dir, std::string study_text, std::string context_text,
                std::vector<std::string> parameter_columns, bool overwrite,
                const std::vector<AlgorithmInfo>& algorithms = {}, std::optional<StudyRunKeys> keys = {});
    ~StudyWriter();
    StudyWriter(const StudyWriter&) = delete;
    StudyWriter& operator=(const StudyWriter&) = delete;

    // The study's runs whose record is in the store, and succeeded: a run whose stored record is
    // a failure (an external program that crashed, an optimiser that threw) is not completed, so
    // that the same command computes it again; retried_failures() counts those.
    [[nodiscard]] const std::set<std::int64_t>& completed() const { return completed_; }
    [[nodiscard]] std::int64_t retried_failures() const { return retried_failures_; }
    [[nodiscard]] const std::filesystem::path& directory() const { return dir_; }
    // What opening the store found to say (damaged records), one line each, for the user.
    [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }
    void set_sync_policy(const StoreSyncPolicy& policy) { sync_policy_ = policy; }
    // The size store.bin had when it was last synced: every block written before then is on disk.
    [[nodiscard]] std::uint64_t synced_bytes() const { return synced_bytes_; }
    // Stores one finished run (thread-safe; the block is written in one go, and synced when the
    // sync policy says so).
    void append(const RunRecord& record, double wall_seconds);

    // Writes the sorted result files of every run of the study, runs.csv last, after checking that
    // the store holds exactly the study's runs (throws std::runtime_error naming the first one
    // missing, or a study.ini changed since) and syncing it. Records are read back from the store
    // a chunk at a time, so memory does not grow with the study. On an error no temporary file is
    // left behind.
    void finish();
    // Of the files finish() wrote.
    [[nodiscard]] const StudySummary& summary() const { return summary_; }

private:
    struct Stored {
        std::uint64_t offset = 0; // of the block's payload in store.bin
        std::uint64_t size = 0;
        std::string slot;
        bool failed = false; // the record is a failed run's
    };
    // A stored block whose record cannot be trusted (checksum, or decoding).
    struct Damaged {
        std::uint64_t offset = 0;
        std::string identity; // as far as it could be read
    };
    [[nodiscard]] RunKey key_of(std::int64_t run_id, const RunRecord* record) const;
    void load_store();
    void index_block(std::uint64_t offset, std::string_view payload);
    void check_changes(bool overwrite);
    void warn_damaged();
    [[nodiscard]] std::string run_name(std::int64_t run_id) const;
    [[nodiscard]] std::optional<std::int64_t> unkeyed_run_id(std::string_view identity) const;
    [[nodiscard]] std::vector<std::int64_t> runs_to_render() const;
    void sync_if_due();
    void sync_store();
    // Rendering the result files (study_rendering.cpp).
    struct RenderedChunk; // the lines and summary of a chunk of runs
    [[nodiscard]] DecodedRecord stored_record(std::int64_t run_id, std::string_view payload) const;
    [[nodiscard]] RenderedChunk render_chunk(const StoreReader& in, std::span<const std::int64_t> ids) const;
    void render_files(const std::vector<std::int64_t>& ids);

    std::filesystem::path dir_;
    std::string study_text_;
    std::vector<std::string> parameter_columns_;
    std::optional<StudyRunKeys> keys_;
    std::string unkeyed_suffix_; // of identities without keys: " of study <hash of the study text>"
    std::mutex mutex_;
    int store_fd_ = -1;                             // store.bin, written with pwrite
    std::atomic<std::uint64_t> store_size_{0};      // bytes in store.bin: where the next block goes
    std::unordered_map<std::string, Stored> index_; // identity -> where its newest block is
    std::vector<std::string> identities_;           // of the study's runs, by run_id (with keys)
    std::set<std::int64_t> completed_;
    std::int64_t retried_failures_ = 0;
    std::vector<Damaged> damaged_;
    std::vector<std::string> warnings_;
    StudySummary summary_;

    StoreSyncPolicy sync_policy_;
    std::mutex sync_mutex_; // one sync at a time; others do not wait for it
    std::atomic<std::int64_t> unsynced_runs_{0};
    std::atomic<std::int64_t> last_sync_ns_{0}; // steady clock
    std::atomic<std::uint64_t> synced_bytes_{0};
};

// True when `dir` is a mhbench study directory (see above).
bool is_study_directory(const std::filesystem::path& dir);

// The header of runs.csv for the given parameter columns.
std::string runs_csv_header(const std::vector<std::string>& parameter_columns);

// A file rendered from the store (runs.csv, curves.csv, ...) as it was written: its size and
// CRC-32C. These files are not synced (the store they are rendered from is, and they are 100 MB
// for 10^5 runs): the marker, which is synced, names them, and load_study refuses any that a
// crash of the machine left different (rendered again by running the same command again).
struct RenderedFile {
    std::string name;
    std::uint64_t size = 0;
    std::uint32_t checksum = 0; // CRC-32C
};

// The text of .mhbench-study: the format, and once a study is finished, the checksum of the
// study.ini its runs.csv was rendered for, the number of runs in it (`runs` < 0: unfinished) and
// each rendered file's size and checksum ("runs.csv = 1234 bytes, crc32c 0a1b2c3d").
std::string study_marker(std::string_view study_text, std::int64_t runs = -1,
                         const std::vector<RenderedFile>& rendered = {});
// The CRC-32C of a study.ini's text, in hex, as the marker names it.
std::string study_checksum(std::string_view study_text);
// How the marker states a rendered file: "1234 bytes, crc32c 0a1b2c3d".
std::string rendered_file_facts(std::uint64_t size, std::uint32_t checksum);

struct StudyData {
    std::filesystem::path directory;
    std::string study_text;
    std::string context_text;
    std::vector<std::string> parameter_columns;
    // In study order; empty for studies written before algorithms.csv existed (then label and
    // full spec are the spec itself).
    std::vector<AlgorithmInfo> algorithms;
    std::vector<RunRecord> runs; // sorted by run_id, with curve, checkpoints and improvements filled in
    std::map<std::int64_t, double> wall_seconds;
    // What the reader has to say about the directory, one line each: a study without its marker.
    std::vector<std::string> warnings;
};

// Reads a finished study directory. Throws std::runtime_error naming the file (and line) when
// a file is missing, truncated or malformed, or when the directory holds an unfinished study. The
// rendered files must be those the marker names (size and CRC-32C); without a marker, those of a
// study with store.bin must be what it renders (store_check.hpp), and a study of format 2 (no
// store.bin) is read as it is.
StudyData load_study(const std::filesystem::path& dir);

} // namespace mhb
