// Walking store.bin block by block (see store_scan.hpp).
#include "results/store/store_scan.hpp"

#include <algorithm>
#include <string>

#include "results/store/record_codec.hpp"
#include "results/store/store_block.hpp"

namespace mhb {

namespace {

// The first position >= from where `block_magic` starts, or `size` when none does.
std::uint64_t find_magic(const StoreReader& in, std::uint64_t from, std::uint64_t size) {
    constexpr std::uint64_t window = 1 << 16;
    std::string chunk;
    while (from + block_magic.size() <= size) {
        in.read(from, std::min(window, size - from), chunk);
        const auto found = std::string_view(chunk).find(block_magic);
        if (found != std::string_view::npos)
            return from + found;
        from += chunk.size() - (block_magic.size() - 1); // a magic may straddle two windows
    }
    return size;
}

} // namespace

std::uint64_t scan_store_blocks(const StoreReader& in, std::uint64_t file_size,
                                const std::function<void(std::uint64_t, std::string_view)>& each) {
    constexpr std::uint64_t header_size = block_magic.size() + 8;
    // The file is scanned through a window of a few MB, not one read per block: a store may hold
    // 10^6 runs.
    constexpr std::uint64_t window = std::uint64_t{4} << 20;
    std::string buffer;
    std::uint64_t buffer_start = 0;
    const auto view = [&](std::uint64_t at, std::uint64_t length) {
        if (at < buffer_start || at + length > buffer_start + buffer.size()) {
            buffer_start = at;
            in.read(at, std::min(std::max(length, window), file_size - at), buffer);
        }
        return std::string_view(buffer).substr(static_cast<std::size_t>(at - buffer_start),
                                               static_cast<std::size_t>(length));
    };
    std::uint64_t position = 0;
    std::uint64_t good_end = 0; // just past the last complete block
    while (position + header_size + block_end.size() <= file_size) {
        const std::string_view header = view(position, header_size);
        bool complete = header.substr(0, block_magic.size()) == block_magic;
        std::uint64_t size = 0;
        if (complete) {
            ByteReader size_reader(header.substr(block_magic.size()), "store.bin");
            size = size_reader.u64();
            // Cut short (or corrupt): never allocate for it.
            complete = size <= file_size - position - header_size - block_end.size();
        }
        if (complete)
            complete = view(position + header_size + size, block_end.size()) == block_end;
        if (complete) {
            each(position + header_size, view(position + header_size, size));
            position += header_size + size + block_end.size();
            good_end = position;
        } else {
            position = find_magic(in, position + 1, file_size);
        }
    }
    return good_end;
}

} // namespace mhb
