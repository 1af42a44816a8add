#include "results/crc32c.hpp"

#include <boost/crc.hpp>
#include <cstring>

namespace mhb {
namespace {

#if defined(__x86_64__)
// SSE4.2's crc32 computes CRC-32C, 8 bytes an instruction: several times Boost.CRC's speed, which
// matters for a store of 10^5 records checked when written, opened and rendered.
__attribute__((target("sse4.2"))) std::uint32_t crc32c_instruction(std::string_view bytes) {
    std::uint64_t state = 0xFFFFFFFFU;
    std::size_t i = 0;
    for (; i + 8 <= bytes.size(); i += 8) {
        std::uint64_t word = 0;
        std::memcpy(&word, bytes.data() + i, 8);
        state = __builtin_ia32_crc32di(state, word);
    }
    auto narrow = static_cast<std::uint32_t>(state);
    for (; i < bytes.size(); ++i)
        narrow = __builtin_ia32_crc32qi(narrow, static_cast<unsigned char>(bytes[i]));
    return ~narrow;
}
#endif

} // namespace

std::uint32_t crc32c(std::string_view bytes) {
#if defined(__x86_64__)
    static const bool has_instruction = __builtin_cpu_supports("sse4.2");
    if (has_instruction)
        return crc32c_instruction(bytes);
#endif
    return detail::crc32c_portable(bytes);
}

std::uint32_t detail::crc32c_portable(std::string_view bytes) {
    // Castagnoli's polynomial, reflected in and out, all ones in and out: CRC-32C.
    boost::crc_optimal<32, 0x1EDC6F41U, 0xFFFFFFFFU, 0xFFFFFFFFU, true, true> state;
    state.process_bytes(bytes.data(), bytes.size());
    return state.checksum();
}

} // namespace mhb
