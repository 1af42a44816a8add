// What a StudyWriter finds in an existing store.bin when it opens a study: the blocks scanned and
// indexed (a half-written end cut off), the stored runs of this study, the runs that changed under
// a stored one, and the damaged records to warn about (see study_writer.hpp).
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <stdexcept>

#include "results/store/record_codec.hpp"
#include "results/store/run_key.hpp"
#include "results/store/store_block.hpp"
#include "results/store/store_scan.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_writer.hpp"

namespace mhb {
namespace fs = std::filesystem;

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
    // A framed block is kept in the file even when its record is damaged: that only leaves it out
    // of the index.
    const std::uint64_t good_end = scan_store_blocks(
        in, file_size, [&](std::uint64_t offset, std::string_view payload) { index_block(offset, payload); });
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
        reader.skip_text();                   // facts
        reader.skip_text();                   // notes
        if (check == PayloadCheck::unchecked) // no checksum: it must at least decode
            stored.failed = !decode_record(reader, true).record.ok;
        else
            stored.failed = !record_succeeded(reader);
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
        if (const auto stored = index_.find(identities_[i]); stored != index_.end()) {
            // A failed record is no result: the run is computed again, and its new record replaces
            // it (the newest block of an identity is the one used).
            if (stored->second.failed)
                ++retried_failures_;
            else
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

} // namespace mhb
