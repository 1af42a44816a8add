#include "results/store/store_block.hpp"

#include "results/store/crc32c.hpp"
#include "results/store/record_codec.hpp"

namespace mhb {
namespace {

constexpr std::string_view checksum_tag = "MHBCRC4\n";
constexpr std::size_t trailer_size = checksum_tag.size() + 8;

std::uint64_t read_u64(std::string_view bytes) {
    std::uint64_t value = 0;
    for (std::size_t i = 0; i < 8; ++i)
        value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[i])) << (8 * i);
    return value;
}

} // namespace

std::string store_block(const RunKey& key, const RunRecord& record, double wall_seconds) {
    ByteWriter payload;
    payload.text(key.identity);
    payload.text(key.slot);
    payload.text(key.facts);
    payload.text(key.notes);
    encode_record(payload, record, wall_seconds);
    const std::uint32_t checksum = crc32c(payload.bytes());
    ByteWriter trailer;
    trailer.u64(checksum);
    ByteWriter size;
    size.u64(payload.bytes().size() + trailer_size);
    std::string block;
    block.reserve(block_header_size + payload.bytes().size() + trailer_size + block_end.size());
    block.append(block_magic).append(size.bytes()).append(payload.bytes());
    block.append(checksum_tag).append(trailer.bytes()).append(block_end);
    return block;
}

PayloadCheck check_payload(std::string_view payload) {
    // A format-3 record ends with its end-of-sections mark (u64 0) after the last section or
    // wall_seconds: the tag's bytes there would be a 1e-260 wall time or section value. A flip
    // inside the tag itself leaves the record's bytes intact, and decoding still checks them.
    if (payload.size() < trailer_size ||
        payload.substr(payload.size() - trailer_size, checksum_tag.size()) != checksum_tag)
        return PayloadCheck::unchecked;
    const std::string_view body = payload.substr(0, payload.size() - trailer_size);
    const std::uint64_t stored = read_u64(payload.substr(payload.size() - 8));
    return stored == crc32c(body) ? PayloadCheck::intact : PayloadCheck::damaged;
}

} // namespace mhb
