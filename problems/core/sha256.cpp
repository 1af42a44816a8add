#include "problems/core/sha256.hpp"

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <nettle/sha2.h>
#include <stdexcept>

namespace mhb {
namespace {

// A digest as 64 lowercase hex digits.
std::string finish(sha256_ctx& context) {
    std::array<std::uint8_t, SHA256_DIGEST_SIZE> digest{};
    sha256_digest(&context, digest.size(), digest.data());
    static constexpr char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(2 * digest.size());
    for (const std::uint8_t byte : digest) {
        out.push_back(hex[byte >> 4]);
        out.push_back(hex[byte & 0x0f]);
    }
    return out;
}

void update(sha256_ctx& context, const char* data, std::size_t size) {
    sha256_update(&context, size, reinterpret_cast<const std::uint8_t*>(data));
}

} // namespace

std::string sha256_hex(std::string_view bytes) {
    sha256_ctx context;
    sha256_init(&context);
    update(context, bytes.data(), bytes.size());
    return finish(context);
}

std::string sha256_file_hex(const std::filesystem::path& path) {
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path.string() + ": cannot read the file to hash it (" +
                                 (errno != 0 ? std::strerror(errno) : "unknown reason") + ")");
    sha256_ctx context;
    sha256_init(&context);
    std::array<char, 1 << 16> buffer{};
    while (in) {
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        update(context, buffer.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad())
        throw std::runtime_error(path.string() + ": reading the file failed while hashing it");
    return finish(context);
}

std::string short_hash(const std::string& hex, std::size_t digits) {
    return hex.size() <= digits ? hex : hex.substr(0, digits) + "..";
}

} // namespace mhb
