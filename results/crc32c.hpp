// CRC-32C (Castagnoli, the polynomial of iSCSI, ext4 and SSE4.2's crc32 instruction): the
// checksum of each record in store.bin. results/ depends on no other mhbench library, so it keeps
// its own small checksum rather than the SHA-256 of problems/; a CRC detects every burst of up to
// 32 flipped bits, which is what a damaged sector or a stray write leaves.
#pragma once

#include <cstdint>
#include <string_view>

namespace mhb {

// The CRC-32C of `bytes`, continuing from `crc` (the CRC of the bytes before them; 0 to start).
// With the processor's crc32 instruction (SSE4.2) where it has one, from tables otherwise.
std::uint32_t crc32c(std::string_view bytes, std::uint32_t crc = 0);

namespace detail {
// The same from tables alone, whatever the processor (for tests of both ways).
std::uint32_t crc32c_tables(std::string_view bytes, std::uint32_t crc = 0);
} // namespace detail

} // namespace mhb
