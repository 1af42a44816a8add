// StudyWriter: the store of finished runs (store.bin), resuming and growing a study, and the sorted
// result files rendered from it (see store.hpp).
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fcntl.h>
#include <fstream>
#include <memory>
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_pipeline.h>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <unistd.h>

#include "results/store/crc32c.hpp"
#include "results/store/csv.hpp"
#include "results/store/durable_file.hpp"
#include "results/store/record_codec.hpp"
#include "results/store/store.hpp"
#include "results/store/store_block.hpp"

namespace mhb {
namespace fs = std::filesystem;

namespace {

std::string join_numbers(const std::vector<double>& values) {
    std::string out;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0)
            out += ' ';
        out += csv_number(values[i]);
    }
    return out;
}

const char* const result_files[] = {
    StudyFiles::runs,         StudyFiles::curves,  StudyFiles::checkpoints, StudyFiles::trajectories,
    StudyFiles::improvements, StudyFiles::timings, StudyFiles::journal,     StudyFiles::store};

struct Block {
    std::string run_line;
    std::string curve_lines;
    std::string checkpoint_lines;
    std::string trajectory_lines;
    std::string improvement_lines;
    std::string timing_line;
};

// The lines a run contributes to each result file, for the study's parameter columns.
Block render(const RunRecord& r, double wall_seconds, const std::vector<std::string>& columns) {
    Block block;
    const std::string id = std::to_string(r.run_id);
    std::string line =
        id + ',' + csv_field(r.algorithm) + ',' + csv_field(r.problem) + ',' + csv_field(r.budget) + ',' +
        std::to_string(r.run_index) + ',' + std::to_string(r.seed) + ',' + (r.ok ? "ok" : "failed") + ',' +
        std::to_string(r.evaluations) + ',' + std::to_string(r.iterations) + ',' +
        (r.ok ? csv_number(r.best_f) : "") + ',' + csv_optional(r.f_opt) + ',' + csv_optional(r.error()) +
        ',' + (r.evaluations_to_target ? std::to_string(*r.evaluations_to_target) : "") + ',' +
        join_numbers(r.best_x);
    for (const auto& column : columns) {
        std::string value;
        std::string truth;
        std::string optimum;
        std::string error;
        for (std::size_t k = 0; k < r.parameter_names.size(); ++k) {
            if (r.parameter_names[k] != column || k >= r.best_x.size())
                continue;
            value = csv_number(r.best_x[k]);
            if (k < r.x_opt.size())
                optimum = csv_number(r.x_opt[k]);
            if (k < r.true_parameters.size()) {
                truth = csv_number(r.true_parameters[k]);
                if (r.true_parameters[k] != 0.0)
                    error = csv_number(100.0 * (r.best_x[k] - r.true_parameters[k]) / r.true_parameters[k]);
            }
        }
        line += ',' + value + ',' + truth + ',' + optimum + ',' + error;
    }
    block.run_line = line + ',' + csv_field(r.message) + '\n';

    for (const auto& p : r.curve) {
        block.curve_lines += id + ',' + std::to_string(p.iteration) + ',' + std::to_string(p.evaluations) +
                             ',' + csv_number(p.best_f) + '\n';
        if (!r.parameter_names.empty() && !p.best_x.empty()) {
            std::string row = id + ',' + std::to_string(p.iteration);
            for (const auto& column : columns) {
                std::string value;
                for (std::size_t k = 0; k < r.parameter_names.size(); ++k)
                    if (r.parameter_names[k] == column && k < p.best_x.size())
                        value = csv_number(p.best_x[k]);
                row += ',' + value;
            }
            block.trajectory_lines += row + '\n';
        }
    }
    for (const auto& c : r.checkpoints)
        block.checkpoint_lines +=
            id + ',' + std::to_string(c.evaluations) + ',' + csv_number(c.best_f) + '\n';
    if (r.improvements) {
        for (const auto& p : r.improvements->points)
            block.improvement_lines +=
                id + ",improvement," + std::to_string(p.evaluations) + ',' + csv_number(p.best_f) + '\n';
        // Also marks the run as one whose improvements were recorded (it may have none: +inf only).
        block.improvement_lines +=
            id + ",last," + std::to_string(r.evaluations) + ',' + csv_number(r.improvements->last_f) + '\n';
    }
    block.timing_line = id + ',' + csv_number(wall_seconds) + '\n';
    return block;
}

std::int64_t steady_now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Reads payloads back by position (pread: no shared file offset, no stream buffer to refill for
// each run). The store is not mapped into memory, so that resident memory stays small.
class StoreReader {
public:
    explicit StoreReader(const fs::path& path)
        : path_(path), fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
        if (fd_ < 0)
            throw std::runtime_error(path.string() + ": cannot be read (" + std::strerror(errno) + ")");
    }
    ~StoreReader() { ::close(fd_); }
    StoreReader(const StoreReader&) = delete;
    StoreReader& operator=(const StoreReader&) = delete;

    void read(std::uint64_t offset, std::uint64_t size, std::string& payload) const {
        payload.resize(static_cast<std::size_t>(size));
        std::size_t done = 0;
        while (done < payload.size()) {
            const ssize_t n =
                ::pread(fd_, payload.data() + done, payload.size() - done, static_cast<off_t>(offset + done));
            if (n <= 0)
                throw std::runtime_error(
                    path_.string() + ": cannot read a stored run back (" +
                    (n < 0 ? std::strerror(errno) : "the file is shorter than its index") + ")");
            done += static_cast<std::size_t>(n);
        }
    }

private:
    fs::path path_;
    int fd_;
};

} // namespace

std::string runs_csv_header(const std::vector<std::string>& parameter_columns) {
    std::string header =
        "run_id,algorithm,problem,budget,run,seed,status,evaluations,iterations,best_f,f_opt,error,"
        "evals_to_target,best_x";
    for (const auto& p : parameter_columns)
        header += "," + p + "," + p + "_true," + p + "_opt," + p + "_err_pct";
    return header + ",message\n";
}

namespace {

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

std::string study_checksum(std::string_view study_text) {
    return crc32c_hex(crc32c(study_text));
}

std::string rendered_file_facts(std::uint64_t size, std::uint32_t checksum) {
    return std::to_string(size) + " bytes, crc32c " + crc32c_hex(checksum);
}

std::string study_marker(std::string_view study_text, std::int64_t runs,
                         const std::vector<RenderedFile>& rendered) {
    std::string text = "mhbench study directory, format 3\n";
    if (runs < 0)
        return text;
    text += "study.ini crc32c = " + study_checksum(study_text) + "\nruns = " + std::to_string(runs) + '\n';
    for (const RenderedFile& file : rendered)
        text += file.name + " = " + rendered_file_facts(file.size, file.checksum) + '\n';
    return text;
}

bool is_study_directory(const fs::path& dir) {
    std::error_code ec;
    if (fs::exists(dir / StudyFiles::marker, ec))
        return true;
    return fs::exists(dir / StudyFiles::study, ec) &&
           (fs::exists(dir / StudyFiles::runs, ec) || fs::exists(dir / StudyFiles::journal, ec));
}

StudyWriter::StudyWriter(fs::path dir, std::string study_text, std::string context_text,
                         std::vector<std::string> parameter_columns, bool overwrite,
                         const std::vector<AlgorithmInfo>& algorithms, std::optional<StudyRunKeys> keys)
    : dir_(std::move(dir)), study_text_(study_text), parameter_columns_(std::move(parameter_columns)),
      keys_(std::move(keys)),
      unkeyed_suffix_(" of study " + std::to_string(std::hash<std::string>{}(study_text))) {
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

    // A changed study is unfinished until finish() writes its files again.
    const bool same_study =
        fs::exists(dir_ / StudyFiles::study) && read_whole_file(dir_ / StudyFiles::study) == study_text;
    if (!same_study)
        fs::remove(dir_ / StudyFiles::runs, ec);
    // A finished study's marker names its study.ini: kept while that study stays.
    if (!same_study || !fs::exists(dir_ / StudyFiles::marker))
        write_file_atomically(dir_ / StudyFiles::marker, study_marker(study_text));
    write_file_atomically(dir_ / StudyFiles::study, study_text);
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

namespace {

// The first position >= from where `block_magic` starts, or `size` when none does.
std::uint64_t find_magic(const StoreReader& in, std::uint64_t from, std::uint64_t size) {
    constexpr std::uint64_t window = 1 << 16;
    std::string chunk;
    while (from + block_magic.size() <= size) {
        in.read(from, std::min(window, size - from), chunk);
        const auto found = std::string_view(chunk).find(block_magic);
        if (found != std::string_view::npos)
            return from + found;
        from += chunk.size() - (block_magic.size() - 1); // a magic may straddle two windows
    }
    return size;
}

} // namespace

void StudyWriter::load_store() {
    const fs::path path = dir_ / StudyFiles::store;
    std::error_code ec;
    if (fs::is_directory(path, ec))
        throw std::runtime_error(path.string() + ": cannot be read (" + std::strerror(EISDIR) + ")");
    if (!fs::exists(path, ec))
        return;
    const std::uint64_t file_size = fs::file_size(path, ec);
    if (ec)
        throw std::runtime_error(path.string() + ": cannot be read (" + ec.message() + ")");
    const StoreReader in(path);
    constexpr std::uint64_t header_size = block_magic.size() + 8;
    // The file is scanned through a window of a few MB, not one read per block: a store may hold
    // 10^6 runs.
    constexpr std::uint64_t window = std::uint64_t{4} << 20;
    std::string buffer;
    std::uint64_t buffer_start = 0;
    const auto view = [&](std::uint64_t at, std::uint64_t length) {
        if (at < buffer_start || at + length > buffer_start + buffer.size()) {
            buffer_start = at;
            in.read(at, std::min(std::max(length, window), file_size - at), buffer);
        }
        return std::string_view(buffer).substr(static_cast<std::size_t>(at - buffer_start),
                                               static_cast<std::size_t>(length));
    };
    std::uint64_t position = 0;
    std::uint64_t good_end = 0; // just past the last complete block
    while (position + header_size + block_end.size() <= file_size) {
        const std::string_view header = view(position, header_size);
        bool complete = header.substr(0, block_magic.size()) == block_magic;
        std::uint64_t size = 0;
        if (complete) {
            ByteReader size_reader(header.substr(block_magic.size()), path.string());
            size = size_reader.u64();
            // Cut short (or corrupt): never allocate for it.
            complete = size <= file_size - position - header_size - block_end.size();
        }
        if (complete)
            complete = view(position + header_size + size, block_end.size()) == block_end;
        if (complete) {
            // Framed whole: kept in the file (a damaged record is only left out of the index).
            index_block(position + header_size, view(position + header_size, size));
            position += header_size + size + block_end.size();
            good_end = position;
        } else {
            // Blocks are written concurrently at reserved positions: one a killed process left
            // half-written may be followed by complete ones. Go on from the next block start.
            position = find_magic(in, position + 1, file_size);
        }
    }
    // Cut a half-written last block off, so that new blocks never follow it.
    if (file_size != good_end)
        fs::resize_file(path, good_end, ec);
    if (ec)
        throw std::runtime_error(path.string() + ": cannot be repaired (" + ec.message() + ")");
    store_size_ = good_end;
    // A run whose damaged record was computed again later has its good record: nothing to say.
    std::erase_if(damaged_, [&](const Damaged& d) { return index_.count(d.identity) != 0; });
}

void StudyWriter::index_block(std::uint64_t offset, std::string_view payload) {
    const PayloadCheck check = check_payload(payload);
    ByteReader reader(payload, (dir_ / StudyFiles::store).string());
    std::string identity;
    try {
        identity = reader.text();
        Stored stored;
        stored.offset = offset;
        stored.size = payload.size();
        stored.slot = reader.text();
        if (check == PayloadCheck::unchecked) {           // no checksum: it must at least decode
            for (int skipped = 0; skipped < 2; ++skipped) // facts, notes
                reader.text();
            (void)decode_record(reader, true);
        }
        if (check != PayloadCheck::damaged) {
            index_[identity] = std::move(stored);
            return;
        }
    } catch (const std::runtime_error&) {
    }
    damaged_.push_back({offset, std::move(identity)});
}

void StudyWriter::check_changes(bool overwrite) {
    std::unordered_map<std::string_view, const std::string*> slot_identity; // of the stored runs
    for (const auto& [identity, stored] : index_)
        slot_identity[stored.slot] = &identity;
    std::vector<std::string> changes;
    std::int64_t changed_runs = 0;
    const std::int64_t count = keys_ ? keys_->count : 0;
    // Every run's key, in parallel (a key costs a SHA-256; a study may have 10^6 runs): its
    // identity, and whether a stored run sits in its slot with another identity.
    identities_.resize(static_cast<std::size_t>(count));
    std::vector<char> slot_taken(static_cast<std::size_t>(count), 0);
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, count, 256), [&](const auto& range) {
        for (std::int64_t id = range.begin(); id != range.end(); ++id) {
            RunKey wanted = keys_->key(id);
            const auto i = static_cast<std::size_t>(id);
            if (index_.count(wanted.identity) == 0 && slot_identity.count(wanted.slot) != 0)
                slot_taken[i] = 1;
            identities_[i] = std::move(wanted.identity);
        }
    });
    for (std::int64_t id = 0; id < count; ++id) {
        const auto i = static_cast<std::size_t>(id);
        if (index_.count(identities_[i]) != 0) {
            completed_.insert(completed_.end(), id);
            continue;
        }
        if (slot_taken[i] == 0)
            continue;
        ++changed_runs;
        const RunKey wanted = keys_->key(id);
        const Stored& stored = index_.at(*slot_identity.at(wanted.slot));
        std::string payload;
        StoreReader(dir_ / StudyFiles::store).read(stored.offset, stored.size, payload);
        ByteReader reader(payload, (dir_ / StudyFiles::store).string());
        RunKey old;
        old.identity = reader.text();
        old.slot = reader.text();
        old.facts = reader.text();
        old.notes = reader.text();
        const std::string change =
            keys_->describe_change ? keys_->describe_change(old, wanted) : "run " + wanted.slot + " changed";
        if (std::find(changes.begin(), changes.end(), change) == changes.end())
            changes.push_back(change);
    }
    if (!keys_) {
        for (const auto& [identity, stored] : index_)
            if (const auto id = unkeyed_run_id(identity))
                completed_.insert(*id);
        return;
    }
    if (changes.empty() || overwrite || keys_->recompute_changed)
        return;
    std::string message = dir_.string() + ": " + std::to_string(changed_runs) + " stored run" +
                          (changed_runs == 1 ? "" : "s") + " would change:";
    constexpr std::size_t shown = 5;
    for (std::size_t i = 0; i < changes.size() && i < shown; ++i)
        message += "\n  " + changes[i];
    if (changes.size() > shown)
        message += "\n  and " + std::to_string(changes.size() - shown) + " more";
    message += "\npass --recompute-changed to compute these runs again (keeping every other stored run), "
               "--overwrite to discard the stored runs and start again, or choose another --out";
    throw std::runtime_error(message);
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

void StudyWriter::warn_damaged() {
    std::unordered_map<std::string_view, std::int64_t> run_of; // damaged identity -> run_id, or -1
    for (const auto& d : damaged_)
        run_of.emplace(d.identity, -1);
    for (std::size_t id = 0; id < identities_.size() && !run_of.empty(); ++id) {
        const auto found = run_of.find(identities_[id]);
        if (found != run_of.end())
            found->second = static_cast<std::int64_t>(id);
    }
    if (!keys_)
        for (auto& [identity, id] : run_of)
            id = unkeyed_run_id(identity).value_or(-1);
    const std::string store = (dir_ / StudyFiles::store).string();
    std::set<std::string_view> said;
    for (const auto& d : damaged_) {
        if (!said.insert(d.identity).second)
            continue;
        const std::int64_t id = run_of.at(d.identity);
        if (id < 0)
            warnings_.push_back(store + ": the record at byte " + std::to_string(d.offset) +
                                " is damaged and not used (if it was a run of this study, it will be "
                                "computed again)");
        else
            warnings_.push_back(store + ": the record of " + run_name(id) +
                                " is damaged; it will be computed again");
    }
}

std::string StudyWriter::run_name(std::int64_t run_id) const {
    std::string name = "run " + std::to_string(run_id);
    if (!keys_)
        return name;
    // The slot, "label | problem | budget | run index", as "(label, problem, budget, run k)".
    std::string slot = keys_->key(run_id).slot;
    const auto last = slot.rfind(" | ");
    if (last != std::string::npos)
        slot.replace(last, 3, ", run ");
    for (auto at = slot.find(" | "); at != std::string::npos; at = slot.find(" | ", at))
        slot.replace(at, 3, ", ");
    return name + " (" + slot + ")";
}

std::optional<std::int64_t> StudyWriter::unkeyed_run_id(std::string_view identity) const {
    std::int64_t id = 0;
    if (identity.rfind("run ", 0) != 0)
        return std::nullopt;
    const auto [end, error] = std::from_chars(identity.data() + 4, identity.data() + identity.size(), id);
    if (error != std::errc() ||
        std::string_view(end, static_cast<std::size_t>(identity.data() + identity.size() - end)) !=
            unkeyed_suffix_)
        return std::nullopt;
    return id;
}

std::vector<std::int64_t> StudyWriter::runs_to_render() const {
    if (!keys_) // runs named by run_id alone: the study is what was stored
        return {completed_.begin(), completed_.end()};
    std::vector<std::int64_t> ids;
    if (keys_->run_ids) {
        ids = *keys_->run_ids;
        std::sort(ids.begin(), ids.end());
    } else {
        ids.resize(static_cast<std::size_t>(keys_->count));
        for (std::size_t i = 0; i < ids.size(); ++i)
            ids[i] = static_cast<std::int64_t>(i);
    }
    for (const std::int64_t id : ids)
        if (id < 0 || id >= keys_->count || index_.count(identities_[static_cast<std::size_t>(id)]) == 0)
            throw std::runtime_error((dir_ / StudyFiles::store).string() + ": holds no record of " +
                                     run_name(id) +
                                     " of study.ini; run the same command again to compute it");
    return ids;
}

void StudyWriter::finish() {
    const std::lock_guard<std::mutex> lock(mutex_);
    {
        const std::lock_guard<std::mutex> syncing(sync_mutex_);
        sync_store();
    }
    const std::vector<std::int64_t> ids = runs_to_render();
    // Another process writing into this directory (it should hold the lock) could have put its
    // study.ini beside the runs of this one.
    if (read_whole_file(dir_ / StudyFiles::study) != study_text_)
        throw std::runtime_error((dir_ / StudyFiles::study).string() +
                                 ": was replaced while this study ran (another mhbench writing into the "
                                 "same directory?); nothing was rendered");
    render_files(ids);
}

void StudyWriter::render_files(const std::vector<std::int64_t>& ids) {
    const StoreReader in(dir_ / StudyFiles::store);
    const auto render_stored = [&](std::int64_t id, std::string_view payload, Block& out,
                                   StudySummary& summary) {
        if (check_payload(payload) == PayloadCheck::damaged)
            throw std::runtime_error((dir_ / StudyFiles::store).string() + ": the record of " + run_name(id) +
                                     " was damaged while the study ran; run the same command again");
        ByteReader reader(payload, (dir_ / StudyFiles::store).string());
        for (int skipped = 0; skipped < 4; ++skipped) // identity, slot, facts, notes
            reader.text();
        DecodedRecord decoded = decode_record(reader, true);
        // The record as this study names it: a run found by identity may come from a study that
        // numbered it differently or read its data file from another path.
        RunRecord& record = decoded.record;
        record.run_id = id;
        if (keys_) {
            if (keys_->names) {
                std::tie(record.algorithm, record.problem) = keys_->names(id);
            } else {
                const RunKey key = keys_->key(id);
                record.algorithm = key.algorithm;
                record.problem = key.problem;
            }
        }
        Block block = render(record, decoded.wall_seconds, parameter_columns_);
        out.run_line += block.run_line;
        out.curve_lines += block.curve_lines;
        out.checkpoint_lines += block.checkpoint_lines;
        out.trajectory_lines += block.trajectory_lines;
        out.improvement_lines += block.improvement_lines;
        out.timing_line += block.timing_line;
        ++summary.runs;
        summary.evaluations += record.evaluations;
        if (!record.ok) {
            ++summary.failed;
            if (summary.first_failures.size() < 3) {
                record.curve.clear();
                record.checkpoints.clear();
                record.improvements.reset();
                summary.first_failures.push_back(std::move(record));
            }
        }
    };
    // Each file is streamed to its temporary name and renamed at the end, runs.csv last. Whatever
    // fails on the way, no temporary file stays behind.
    struct Output {
        fs::path path;
        fs::path temporary;
        std::ofstream out;
        RenderedFile written; // size and checksum of what went to `out`, for the marker
        void put(std::string_view text) {
            out << text;
            written.size += text.size();
            written.checksum = crc32c(text, written.checksum);
        }
    };
    struct Temporaries {
        std::vector<fs::path> paths; // not renamed yet
        ~Temporaries() {
            std::error_code ignored;
            for (const auto& path : paths)
                fs::remove(path, ignored);
        }
    } temporaries;
    const auto open = [&](const char* name) {
        Output o;
        o.path = dir_ / name;
        o.temporary = dir_ / (std::string(name) + ".tmp");
        o.written.name = name;
        errno = 0;
        o.out.open(o.temporary, std::ios::binary | std::ios::trunc);
        if (!o.out)
            throw std::runtime_error(o.path.string() + ": cannot be written (" +
                                     (errno != 0 ? std::strerror(errno) : "unknown reason") + ")");
        temporaries.paths.push_back(o.temporary);
        return o;
    };
    Output runs = open(StudyFiles::runs);
    Output curves = open(StudyFiles::curves);
    Output checkpoints = open(StudyFiles::checkpoints);
    Output trajectories = open(StudyFiles::trajectories);
    Output improvements = open(StudyFiles::improvements);
    Output timings = open(StudyFiles::timings);
    runs.put(runs_csv_header(parameter_columns_));
    curves.put("run_id,iteration,evaluations,best_f\n");
    checkpoints.put("run_id,evaluations,best_f\n");
    std::string trajectory_header = "run_id,iteration";
    for (const auto& p : parameter_columns_)
        trajectory_header += "," + p;
    trajectories.put(trajectory_header + '\n');
    improvements.put("run_id,event,evaluations,f\n");
    timings.put("run_id,wall_seconds\n");

    summary_ = StudySummary{};
    // Records are decoded and rendered in parallel, a chunk of runs at a time, and written in
    // run_id order: the output is the same bytes as a serial loop's.
    constexpr std::size_t chunk = 512;
    struct Rendered {
        Block text;
        StudySummary summary;
    };
    std::size_t next = 0;
    tbb::parallel_pipeline(
        16,
        tbb::make_filter<void, std::pair<std::size_t, std::size_t>>(
            tbb::filter_mode::serial_in_order,
            [&](tbb::flow_control& control) {
                if (next >= ids.size()) {
                    control.stop();
                    return std::pair<std::size_t, std::size_t>{};
                }
                const std::size_t first = next;
                next = std::min(ids.size(), next + chunk);
                return std::pair<std::size_t, std::size_t>{first, next};
            }) &
            tbb::make_filter<std::pair<std::size_t, std::size_t>, std::shared_ptr<Rendered>>(
                tbb::filter_mode::parallel,
                [&](std::pair<std::size_t, std::size_t> span) {
                    auto out = std::make_shared<Rendered>();
                    // The chunk's blocks, read with one pread per run of neighbouring blocks
                    // (runs finish, and are stored, roughly in run order).
                    std::vector<std::pair<const Stored*, std::int64_t>> blocks;
                    for (std::size_t k = span.first; k < span.second; ++k) {
                        const auto found = index_.find(keys_ ? identities_[static_cast<std::size_t>(ids[k])]
                                                             : key_of(ids[k], nullptr).identity);
                        if (found != index_.end())
                            blocks.emplace_back(&found->second, ids[k]);
                    }
                    std::vector<std::string_view> payloads(blocks.size());
                    std::vector<std::size_t> by_offset(blocks.size());
                    for (std::size_t i = 0; i < by_offset.size(); ++i)
                        by_offset[i] = i;
                    std::sort(by_offset.begin(), by_offset.end(), [&](std::size_t a, std::size_t b) {
                        return blocks[a].first->offset < blocks[b].first->offset;
                    });
                    std::deque<std::string>
                        buffers; // a deque: growing it moves no string the views point into
                    constexpr std::uint64_t gap = 1 << 12;
                    constexpr std::uint64_t limit = std::uint64_t{8} << 20;
                    for (std::size_t g = 0; g < by_offset.size();) {
                        const std::uint64_t start = blocks[by_offset[g]].first->offset;
                        std::uint64_t stop = start + blocks[by_offset[g]].first->size;
                        std::size_t h = g + 1;
                        while (h < by_offset.size()) {
                            const Stored& neighbour = *blocks[by_offset[h]].first;
                            if (neighbour.offset > stop + gap ||
                                neighbour.offset + neighbour.size - start > limit)
                                break;
                            stop = std::max(stop, neighbour.offset + neighbour.size);
                            ++h;
                        }
                        buffers.emplace_back();
                        in.read(start, stop - start, buffers.back());
                        for (std::size_t i = g; i < h; ++i) {
                            const Stored& b = *blocks[by_offset[i]].first;
                            payloads[by_offset[i]] = std::string_view(buffers.back())
                                                         .substr(static_cast<std::size_t>(b.offset - start),
                                                                 static_cast<std::size_t>(b.size));
                        }
                        g = h;
                    }
                    for (std::size_t i = 0; i < blocks.size(); ++i)
                        render_stored(blocks[i].second, payloads[i], out->text, out->summary);
                    return out;
                }) &
            tbb::make_filter<std::shared_ptr<Rendered>, void>(
                tbb::filter_mode::serial_in_order, [&](const std::shared_ptr<Rendered>& part) {
                    runs.put(part->text.run_line);
                    curves.put(part->text.curve_lines);
                    checkpoints.put(part->text.checkpoint_lines);
                    trajectories.put(part->text.trajectory_lines);
                    improvements.put(part->text.improvement_lines);
                    timings.put(part->text.timing_line);
                    summary_.runs += part->summary.runs;
                    summary_.failed += part->summary.failed;
                    summary_.evaluations += part->summary.evaluations;
                    for (auto& failure : part->summary.first_failures)
                        if (summary_.first_failures.size() < 3)
                            summary_.first_failures.push_back(std::move(failure));
                }));
    // The rendered files are not synced: the store they come from is, and the marker (synced
    // before runs.csv appears) holds each one's size and checksum, so that load_study refuses one
    // that a crash of the machine left short or stale. Syncing them cost 5-8 % of a study of
    // 10^5 short runs (BENCHMARKS.md).
    std::vector<RenderedFile> rendered;
    for (Output* o : {&curves, &checkpoints, &trajectories, &improvements, &timings, &runs}) {
        o->out.close();
        if (!o->out)
            throw std::runtime_error(o->path.string() + ": writing failed (" + std::strerror(errno) + ")");
        rendered.push_back(o->written);
        if (o == &runs) // the study this runs.csv belongs to, and what it and the others hold
            write_file_atomically(dir_ / StudyFiles::marker,
                                  study_marker(study_text_, static_cast<std::int64_t>(ids.size()), rendered));
        std::error_code ec;
        fs::rename(o->temporary, o->path, ec);
        if (ec)
            throw std::runtime_error(o->path.string() + ": cannot be written (" + ec.message() + ")");
        std::erase(temporaries.paths, o->temporary);
    }
    sync_directory(dir_);
}

} // namespace mhb
