// CRC-32C (Castagnoli, the polynomial of iSCSI, ext4 and SSE4.2's crc32 instruction): the
// checksum of each record in store.bin: small and fast, where the SHA-256 of problems/core/ would
// be neither; a CRC detects every burst of up to 32 flipped bits, which is what a damaged sector
// or a stray write leaves.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace mhb {

// The CRC-32C of `bytes`.
// With the processor's crc32 instruction (SSE4.2) where it has one, with Boost.CRC otherwise.
std::uint32_t crc32c(std::string_view bytes);
// The same continued: the CRC-32C of bytes that follow bytes whose CRC-32C was `previous`, so that
// crc32c(a + b) == crc32c(b, crc32c(a)) (a file's checksum computed as it is written, in parts).
std::uint32_t crc32c(std::string_view bytes, std::uint32_t previous);

// A checksum as files name it: eight lower-case hex digits.
std::string crc32c_hex(std::uint32_t checksum);

namespace detail {
// The same by Boost.CRC, whatever the processor (for tests of both ways).
std::uint32_t crc32c_portable(std::string_view bytes, std::uint32_t previous = 0);
} // namespace detail

} // namespace mhb
