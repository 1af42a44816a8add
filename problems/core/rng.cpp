#include "problems/core/rng.hpp"

#include <cmath>

#include "problems/core/fnv1a.hpp"

namespace mhb {

std::uint64_t stable_hash(std::string_view text) noexcept {
    return fnv1a_64(text);
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

void Rng::jump() noexcept {
    // The jump polynomial of xoshiro256** for 2^128 steps (Blackman, Vigna, xoshiro256starstar.c):
    // the state after the jump is the sum over GF(2) of the states s, T s, T^2 s, ... selected by
    // the polynomial's bits. tests/unit/problems/rng_jump_reference.py checks it equals T^(2^128).
    static constexpr std::uint64_t polynomial[4] = {0x180ec6d33cfd0abaULL, 0xd5a61266f0c9392cULL,
                                                    0xa9582618e03fc9aaULL, 0x39abdc4529b1661cULL};
    std::uint64_t jumped[4] = {0, 0, 0, 0};
    for (const std::uint64_t word : polynomial)
        for (int bit = 0; bit < 64; ++bit) {
            if ((word >> bit) & 1U)
                for (int k = 0; k < 4; ++k)
                    jumped[k] ^= s_[k];
            static_cast<void>(next());
        }
    for (int k = 0; k < 4; ++k)
        s_[k] = jumped[k];
    has_spare_ = false;
    spare_normal_ = 0.0;
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
