// CRC-32C against the standard check value and the properties the store relies on.
#include <gtest/gtest.h>
#include <string>

#include "results/store/crc32c.hpp"

namespace mhb {
namespace {

TEST(Crc32c, MatchesTheStandardCheckValue) {
    using Crc = std::uint32_t (*)(std::string_view);
    const Crc portable = [](std::string_view bytes) { return detail::crc32c_portable(bytes); };
    for (const Crc crc : {static_cast<Crc>(&crc32c), portable}) { // the instruction's way, and Boost.CRC's
        EXPECT_EQ(crc("123456789"), 0xE3069283U);                 // the catalogue's "check" for CRC-32/ISCSI
        EXPECT_EQ(crc(""), 0U);
        // RFC 3720 (iSCSI), B.4: 32 bytes of zeros, and of 0xff.
        EXPECT_EQ(crc(std::string(32, '\0')), 0x8A9136AAU);
        EXPECT_EQ(crc(std::string(32, '\xff')), 0x62A8AB43U);
    }
}

TEST(Crc32c, BothWaysAgreeOnEveryLengthAndAlignment) {
    std::string bytes;
    for (int i = 0; i < 300; ++i)
        bytes.push_back(static_cast<char>((i * 131 + 7) & 0xff));
    for (std::size_t start = 0; start < 9; ++start)
        for (std::size_t length = 0; start + length <= bytes.size(); length += 13)
            EXPECT_EQ(crc32c(std::string_view(bytes).substr(start, length)),
                      detail::crc32c_portable(std::string_view(bytes).substr(start, length)));
}

TEST(Crc32c, ContinuesFromThePreviousPartsChecksum) {
    std::string bytes;
    for (int i = 0; i < 200; ++i)
        bytes.push_back(static_cast<char>((i * 59 + 3) & 0xff));
    const std::string_view all(bytes);
    for (std::size_t cut = 0; cut <= all.size(); cut += 11) {
        EXPECT_EQ(crc32c(all.substr(cut), crc32c(all.substr(0, cut))), crc32c(all)) << cut;
        EXPECT_EQ(detail::crc32c_portable(all.substr(cut), detail::crc32c_portable(all.substr(0, cut))),
                  crc32c(all))
            << cut;
    }
}

TEST(Crc32c, SeesEveryFlippedBit) {
    std::string bytes;
    for (int i = 0; i < 1000; ++i)
        bytes.push_back(static_cast<char>((i * 37) & 0xff));
    const std::uint32_t whole = crc32c(bytes);
    for (std::size_t at = 0; at < bytes.size(); at += 7)
        for (int bit = 0; bit < 8; ++bit) {
            std::string damaged = bytes;
            damaged[at] = static_cast<char>(damaged[at] ^ (1 << bit));
            EXPECT_NE(crc32c(damaged), whole) << at << ' ' << bit;
        }
}

} // namespace
} // namespace mhb
