#include "problems/rng.hpp"

#include <cmath>

namespace mhb {

std::uint64_t stable_hash(std::string_view text) noexcept {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : text) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ULL;
    }
    return h;
}

std::uint64_t mix64(std::uint64_t x) noexcept {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

std::uint64_t derive_seed(std::uint64_t study_seed, std::string_view algorithm_spec,
                          std::string_view problem_spec, std::uint64_t run_index) noexcept {
    // Each ingredient is mixed in turn, so that swapping algorithm and problem names, or moving
    // a character from one to the other, gives another stream.
    std::uint64_t h = mix64(study_seed);
    h = mix64(h ^ stable_hash(algorithm_spec));
    h = mix64(h ^ (stable_hash(problem_spec) + 0x632be59bd9b4e019ULL));
    h = mix64(h ^ run_index);
    return h;
}

std::uint64_t derive_seed(std::uint64_t study_seed, std::string_view problem_spec,
                          std::uint64_t run_index) noexcept {
    // A tag of its own in place of the algorithm, so no algorithm's per-algorithm stream can
    // coincide with the common one.
    std::uint64_t h = mix64(study_seed ^ 0x5bd1e9955bd1e995ULL);
    h = mix64(h ^ (stable_hash(problem_spec) + 0x632be59bd9b4e019ULL));
    h = mix64(h ^ run_index);
    return h;
}

Rng::Rng(std::uint64_t seed) noexcept {
    std::uint64_t x = seed;
    for (auto& s : s_) {
        x += 0x9e3779b97f4a7c15ULL;
        std::uint64_t z = x;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        s = z ^ (z >> 31);
    }
}

namespace {
// __extension__ keeps -Wpedantic quiet about the GCC/Clang 128-bit type Lemire's method needs.
__extension__ using Uint128 = unsigned __int128;
} // namespace

std::uint64_t Rng::below(std::uint64_t n) noexcept {
    // Lemire (2019), "Fast random integer generation in an interval".
    std::uint64_t x = next();
    Uint128 m = static_cast<Uint128>(x) * n;
    auto low = static_cast<std::uint64_t>(m);
    if (low < n) {
        const std::uint64_t threshold = (0 - n) % n;
        while (low < threshold) {
            x = next();
            m = static_cast<Uint128>(x) * n;
            low = static_cast<std::uint64_t>(m);
        }
    }
    return static_cast<std::uint64_t>(m >> 64);
}

std::uint64_t Rng::below_except(std::uint64_t n, std::uint64_t excluded) noexcept {
    const std::uint64_t j = below(n - 1);
    return j >= excluded ? j + 1 : j;
}

double Rng::normal() noexcept {
    if (has_spare_) {
        has_spare_ = false;
        return spare_normal_;
    }
    double u = 0;
    double v = 0;
    double s = 0;
    do {
        u = 2.0 * uniform() - 1.0;
        v = 2.0 * uniform() - 1.0;
        s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double factor = std::sqrt(-2.0 * std::log(s) / s);
    spare_normal_ = v * factor;
    has_spare_ = true;
    return u * factor;
}

} // namespace mhb
