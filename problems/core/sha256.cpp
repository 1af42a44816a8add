#include "problems/core/sha256.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <openssl/evp.h>
#include <stdexcept>

namespace mhb {
namespace {

struct DigestContextDeleter {
    void operator()(EVP_MD_CTX* context) const { EVP_MD_CTX_free(context); }
};
using DigestContext = std::unique_ptr<EVP_MD_CTX, DigestContextDeleter>;

DigestContext start_digest() {
    DigestContext context(EVP_MD_CTX_new());
    if (!context || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("sha256: OpenSSL could not start a digest");
    return context;
}

void update(EVP_MD_CTX* context, const char* data, std::size_t size) {
    if (EVP_DigestUpdate(context, data, size) != 1)
        throw std::runtime_error("sha256: OpenSSL could not update a digest");
}

std::string finish(EVP_MD_CTX* context) {
    std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
    unsigned int size = 0;
    if (EVP_DigestFinal_ex(context, digest.data(), &size) != 1)
        throw std::runtime_error("sha256: OpenSSL could not finish a digest");
    static constexpr char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(2 * size);
    for (unsigned int i = 0; i < size; ++i) {
        out.push_back(hex[digest[i] >> 4]);
        out.push_back(hex[digest[i] & 0x0f]);
    }
    return out;
}

} // namespace

std::string sha256_hex(std::string_view bytes) {
    const DigestContext context = start_digest();
    update(context.get(), bytes.data(), bytes.size());
    return finish(context.get());
}

std::string sha256_file_hex(const std::filesystem::path& path) {
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path.string() + ": cannot read the file to hash it (" +
                                 (errno != 0 ? std::strerror(errno) : "unknown reason") + ")");
    const DigestContext context = start_digest();
    std::array<char, 1 << 16> buffer{};
    while (in) {
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        update(context.get(), buffer.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad())
        throw std::runtime_error(path.string() + ": reading the file failed while hashing it");
    return finish(context.get());
}

std::string short_hash(const std::string& hex, std::size_t digits) {
    return hex.size() <= digits ? hex : hex.substr(0, digits) + "..";
}

} // namespace mhb
