// FNV-1a, 64 bits: the one hash of text whose value mhbench keeps (the seeds of random streams
// through stable_hash in rng.hpp, the function ids of the IOHprofiler export). FNV-1a because its
// value is the same across runs, compilers, standard libraries and platforms, unlike std::hash,
// and it takes a few lines. Header-only: results/ uses the same code, and rng.cpp's stable_hash,
// part of the plug-in contract, is this function.
#pragma once

#include <cstdint>
#include <string_view>

namespace mhb {

// FNV-1a, 64 bit (Fowler, Noll, Vo).
constexpr std::uint64_t fnv1a_64(std::string_view text) noexcept {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : text) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ULL;
    }
    return h;
}

} // namespace mhb
