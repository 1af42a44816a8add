// StudyWriter: how a study directory is written (study_files.hpp lists its files). Each finished
// run is appended to store.bin as it finishes; finish() renders runs.csv and the other files from
// it. The writer's code is study_writer.cpp, study_writer_resume.cpp and study_rendering.cpp.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "results/store/algorithm_info.hpp"
#include "results/store/run_key.hpp"
#include "results/store/run_record.hpp"

namespace mhb {

struct DecodedRecord;
class StoreReader; // internal to the study writer (study_writer_internal.hpp)

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
    StudyWriter(std::filesystem::path dir, std::string study_text, const std::string& context_text,
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
    // The record the store holds for a run of this study (its newest block), read back; none when
    // it holds none. Not while runs are being appended (runs by precision read between rounds).
    [[nodiscard]] std::optional<RunRecord> stored_run(std::int64_t run_id);
    // Narrows the runs finish() renders, and requires, to `run_ids` (runs by precision decide them
    // as the study goes). Needs keys.
    void render_only(std::vector<std::int64_t> run_ids);

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

} // namespace mhb
