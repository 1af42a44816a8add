// The data archives the executable carries (problems/cec/data/cec<year>.tar, each member
// compressed alone by xz; embedded by cec_archives.cpp). Only cec_data.cpp reads them.
#pragma once

#include <span>
#include <string_view>

#include "problems/cec/cec_data.hpp"

namespace mhb::cec {

// The archive's bytes, as packed by scripts/pack-cec-data.sh.
std::span<const unsigned char> embedded_archive(Suite suite);

// problems/cec/data/SHA256SUMS as shipped: "<hex>  <year>/input_data/<name>" per line.
std::string_view embedded_sha256sums();

// The SHA-256 of the two archives together, as CMake computed it when it configured the build.
std::string_view embedded_archive_hash();

} // namespace mhb::cec
