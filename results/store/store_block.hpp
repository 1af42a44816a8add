// One block of store.bin: a finished run with its key, framed so that a torn write is found and
// checksummed so that a damaged one is.
//
//   "MHBRUN3\n", u64 payload size, payload, "MHBEND3\n"
//   payload: identity, slot, facts, notes (length-prefixed texts), the encoded record
//            (record_codec.hpp), then, since block format 4, a trailer: "MHBCRC4\n" and the
//            CRC-32C of every payload byte before it (u64)
//
// The framing keeps its format-3 marks on purpose: an older mhbench takes a block it does not
// recognise for a torn write and cuts it off, whereas it reads a format-4 block as a format-3 one
// (its decoder stops at the record's end and never looks at the trailer).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "results/store/run_key.hpp"
#include "results/store/run_record.hpp"

namespace mhb {

// The framing of store.bin's blocks (above): format 4 adds a checksum to each; blocks
// of format 3 carry none and are still read. Not part of a run's identity: a checksum changes no
// value, so the runs of a format-3 store are reused as they are.
inline constexpr int store_block_format = 4;

inline constexpr std::string_view block_magic = "MHBRUN3\n";
inline constexpr std::string_view block_end = "MHBEND3\n";
inline constexpr std::uint64_t block_header_size = block_magic.size() + 8; // magic, payload size

// The whole block of one run, trailer included.
std::string store_block(const RunKey& key, const RunRecord& record, double wall_seconds);

enum class PayloadCheck {
    intact,    // its checksum matches
    damaged,   // its checksum does not match: never to be trusted
    unchecked, // written before checksums (block format 3): only decoding it can tell
};
PayloadCheck check_payload(std::string_view payload);

} // namespace mhb
