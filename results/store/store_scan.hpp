// The complete blocks of store.bin, in file order: what the writer indexes when it opens a study
// (study_writer_resume.cpp) and what load_study checks the rendered files against when a study
// has lost its marker (store_check.cpp). Internal to results/store.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>

#include "results/store/study_writer_internal.hpp"

namespace mhb {

// Calls `each(payload_offset, payload)` for every block framed whole (magic, size, end mark) in
// the first `file_size` bytes of `in`, and returns where the last of them ends. A torn block is
// skipped: blocks are written concurrently at reserved positions, so one a killed process left
// half-written may be followed by complete ones. The payload is not checked (check_payload).
std::uint64_t scan_store_blocks(const StoreReader& in, std::uint64_t file_size,
                                const std::function<void(std::uint64_t, std::string_view)>& each);

} // namespace mhb
