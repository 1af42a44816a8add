// A run's key in store.bin: what determines its record (its identity) and how a user names it, and
// the keys of the runs of the study being written. The runner computes them
// (runner/execution/run_identity.hpp); the writer keeps each with its record (store_block.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mhb {

// The format of store.bin and of the records in it; part of every run's identity, so a change to
// what a record holds makes earlier stores refuse to be mixed with new runs. What is only added to
// a record (the improvement trace) is a section of it (record_codec.hpp) instead: the values of a
// stored run are still those this mhbench computes, so it stays usable, without the new section.
inline constexpr int store_format_version = 3;

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

} // namespace mhb
