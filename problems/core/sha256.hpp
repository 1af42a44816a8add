// SHA-256 of bytes and of files (GNU Nettle), as lowercase hex. Used wherever a result
// must be tied to the exact content it came from: a dataset behind `pmsm:data=`, a run's identity
// in the study store. Nettle rather than OpenSSL: its digest needs no start-up (OpenSSL 3 loads
// its providers at the first digest, about 1 ms of every process) and libarchive loads it anyway.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace mhb {

// 64 lowercase hex digits.
std::string sha256_hex(std::string_view bytes);

// The SHA-256 of a file's content; std::runtime_error naming the file and the OS's reason when it
// cannot be read.
std::string sha256_file_hex(const std::filesystem::path& path);

// The first `digits` hex digits and "..", as messages show a hash ("3f2a9c01..").
std::string short_hash(const std::string& hex, std::size_t digits = 8);

} // namespace mhb
