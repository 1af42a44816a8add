// StudyWriter: preparing a study directory (resuming and growing a study) and appending finished
// runs to its store.bin, synced as the policy says (see study_writer.hpp). Opening an existing store is in
// study_writer_resume.cpp, rendering the result files in study_rendering.cpp.
#include "results/store/study_writer.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>

#include "results/store/algorithm_info.hpp"
#include "results/store/csv.hpp"
#include "results/store/durable_file.hpp"
#include "results/store/run_key.hpp"
#include "results/store/store_block.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_marker.hpp"

namespace mhb {
namespace fs = std::filesystem;

namespace {

const char* const result_files[] = {
    StudyFiles::runs,         StudyFiles::curves,  StudyFiles::checkpoints, StudyFiles::trajectories,
    StudyFiles::improvements, StudyFiles::timings, StudyFiles::journal,     StudyFiles::store};

std::int64_t steady_now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Whether `dir` holds anything besides what a writer leaves before the study's marker exists: the
// lock it takes first, and the marker's temporary file when it was killed while writing it (the
// marker is the first file a study writes).
bool holds_other_files(const fs::path& dir) {
    const std::string marker_in_writing = std::string(StudyFiles::marker) + ".tmp";
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name != StudyFiles::lock && name != marker_in_writing)
            return true;
    }
    return false;
}

} // namespace

StudyWriter::StudyWriter(fs::path dir, std::string study_text, const std::string& context_text,
                         std::vector<std::string> parameter_columns, bool overwrite,
                         const std::vector<AlgorithmInfo>& algorithms, std::optional<StudyRunKeys> keys)
    : dir_(std::move(dir)), study_text_(std::move(study_text)),
      parameter_columns_(std::move(parameter_columns)), keys_(std::move(keys)),
      unkeyed_suffix_(" of study " + std::to_string(std::hash<std::string>{}(study_text_))) {
    std::error_code ec;
    if (fs::is_directory(dir_, ec) && holds_other_files(dir_) && !is_study_directory(dir_))
        throw std::runtime_error(dir_.string() + ": is not empty and is not a mhbench study (it has no " +
                                 StudyFiles::marker +
                                 "); its files are left alone: choose a new or empty --out");
    fs::create_directories(dir_, ec);
    if (ec || !fs::is_directory(dir_))
        throw std::runtime_error(dir_.string() + ": cannot create the output directory (" +
                                 (ec ? ec.message() : std::string("not a directory")) + ")");
    const bool has_store = fs::exists(dir_ / StudyFiles::store);
    const bool earlier_format =
        !has_store && (fs::exists(dir_ / StudyFiles::journal) || fs::exists(dir_ / StudyFiles::runs));
    if (earlier_format && !overwrite)
        throw std::runtime_error(dir_.string() +
                                 ": holds a study written by an earlier mhbench (no store.bin), which cannot "
                                 "be resumed or extended; choose another --out or pass --overwrite");
    if (overwrite || earlier_format)
        for (const char* name : result_files)
            fs::remove(dir_ / name, ec);
    load_store();
    check_changes(overwrite);
    warn_damaged();

    // A changed study is unfinished until finish() writes its files again; so is one that lost its
    // marker, which alone vouched for the rendered files.
    const bool same_study =
        fs::exists(dir_ / StudyFiles::study) && read_whole_file(dir_ / StudyFiles::study) == study_text_;
    const bool has_marker = fs::exists(dir_ / StudyFiles::marker);
    if (!same_study || !has_marker)
        fs::remove(dir_ / StudyFiles::runs, ec);
    // A finished study's marker names its study.ini: kept while that study stays.
    if (!same_study || !has_marker)
        write_file_atomically(dir_ / StudyFiles::marker, study_marker(study_text_));
    write_file_atomically(dir_ / StudyFiles::study, study_text_);
    write_file_atomically(dir_ / StudyFiles::context, context_text);
    if (algorithms.empty()) {
        fs::remove(dir_ / StudyFiles::algorithms, ec);
    } else {
        std::string table = "algorithm,label,parameters\n";
        for (const auto& a : algorithms)
            table += csv_field(a.spec) + ',' + csv_field(a.label) + ',' + csv_field(a.full_spec) + '\n';
        write_file_atomically(dir_ / StudyFiles::algorithms, table);
    }
    store_fd_ = ::open((dir_ / StudyFiles::store).c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0666);
    if (store_fd_ < 0)
        throw std::runtime_error((dir_ / StudyFiles::store).string() + ": cannot be written (" +
                                 std::strerror(errno) + ")");
    if (!has_store)
        sync_directory(dir_); // the new store.bin's name
    synced_bytes_ = store_size_.load();
    last_sync_ns_ = steady_now_ns();
}

StudyWriter::~StudyWriter() {
    if (store_fd_ < 0)
        return;
    // An interrupted study (Ctrl-C) keeps what it stored; a destructor must not throw.
    try {
        sync_store();
    } catch (const std::runtime_error&) {
    }
    ::close(store_fd_);
}

RunKey StudyWriter::key_of(std::int64_t run_id, const RunRecord* record) const {
    if (keys_)
        return keys_->key(run_id);
    RunKey key;
    key.identity = "run " + std::to_string(run_id) + unkeyed_suffix_;
    key.slot = key.identity;
    if (record != nullptr) {
        key.algorithm = record->algorithm;
        key.problem = record->problem;
    }
    return key;
}

void StudyWriter::append(const RunRecord& record, double wall_seconds) {
    const RunKey key = key_of(record.run_id, &record);
    const std::string block = store_block(key, record, wall_seconds);
    // Each block gets its own byte range and is written there without a lock, so that threads
    // store runs concurrently; only the index update is serialised.
    const std::uint64_t offset = store_size_.fetch_add(block.size());
    std::size_t done = 0;
    while (done < block.size()) {
        const ssize_t n =
            ::pwrite(store_fd_, block.data() + done, block.size() - done, static_cast<off_t>(offset + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            throw std::runtime_error((dir_ / StudyFiles::store).string() + ": writing failed (" +
                                     (n < 0 ? std::strerror(errno) : "no space written") + ")");
        done += static_cast<std::size_t>(n);
    }
    Stored stored;
    stored.offset = offset + block_magic.size() + 8;
    stored.size = block.size() - block_magic.size() - 8 - block_end.size();
    stored.slot = key.slot;
    stored.failed = !record.ok;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        index_[key.identity] = std::move(stored);
        completed_.insert(record.run_id);
    }
    ++unsynced_runs_;
    // Every 8 MB the disk starts on the store's new blocks, so that a sync finds little to write.
    constexpr std::uint64_t writeback_step = std::uint64_t{8} << 20;
    if ((offset + block.size()) / writeback_step != offset / writeback_step)
        start_writeback(store_fd_);
    sync_if_due();
}

void StudyWriter::sync_if_due() {
    const double since = static_cast<double>(steady_now_ns() - last_sync_ns_.load()) * 1e-9;
    if (unsynced_runs_.load() < sync_policy_.runs && since < sync_policy_.seconds)
        return;
    // A thread that finds a sync under way goes on: that sync, or the next, covers its block.
    const std::unique_lock<std::mutex> lock(sync_mutex_, std::try_to_lock);
    if (lock.owns_lock())
        sync_store();
}

void StudyWriter::sync_store() {
    // Blocks written (pwrite returned) before the sync starts are on disk once it returns.
    const std::uint64_t size = store_size_.load();
    unsynced_runs_ = 0;
    last_sync_ns_ = steady_now_ns();
    sync_file(store_fd_, dir_ / StudyFiles::store);
    synced_bytes_ = size;
}

std::string StudyWriter::run_name(std::int64_t run_id) const {
    std::string name = "run " + std::to_string(run_id);
    if (!keys_)
        return name;
    // The slot, "label | problem | budget | run index", as "(label, problem, budget, run k)".
    // Built by appending: GCC 12 warns falsely (-Wstringop-overflow) on replace() in place here.
    const std::string slot = keys_->key(run_id).slot;
    const auto last = slot.rfind(" | ");
    std::string readable;
    std::size_t from = 0;
    for (auto at = slot.find(" | "); at != std::string::npos; at = slot.find(" | ", from)) {
        readable.append(slot, from, at - from).append(at == last ? ", run " : ", ");
        from = at + 3;
    }
    readable.append(slot, from, std::string::npos);
    return name.append(" (").append(readable).append(")");
}

} // namespace mhb
