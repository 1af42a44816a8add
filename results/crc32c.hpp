// CRC-32C (Castagnoli, the polynomial of iSCSI, ext4 and SSE4.2's crc32 instruction): the
// checksum of each record in store.bin. results/ depends on no other mhbench library, so it keeps
// its own small checksum rather than the SHA-256 of problems/; a CRC detects every burst of up to
// 32 flipped bits, which is what a damaged sector or a stray write leaves.
#pragma once

#include <cstdint>
#include <string_view>

namespace mhb {

// The CRC-32C of `bytes`.
// With the processor's crc32 instruction (SSE4.2) where it has one, with Boost.CRC otherwise.
std::uint32_t crc32c(std::string_view bytes);

namespace detail {
// The same by Boost.CRC, whatever the processor (for tests of both ways).
std::uint32_t crc32c_portable(std::string_view bytes);
} // namespace detail

} // namespace mhb
