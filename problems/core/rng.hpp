// Random numbers that are the same on every platform and standard library: xoshiro256** seeded
// through SplitMix64, with our own uniform, integer and normal draws (std:: distributions differ
// between libstdc++ and libc++, and would break bit-for-bit reproducibility).
//
// Every run gets its own stream from a fixed hash of names and numbers — never thread ids or
// time — so results do not depend on scheduling or thread count. By default the hash takes
// (study seed, problem, run index) only: every algorithm of a study starts run r on problem p
// from the same stream (common random numbers, so runs pair across algorithms). The older
// derivation that also hashes the algorithm spec is kept for `seeds = per-algorithm` studies.
// Within a run, an optimiser that wants a second stream takes a jumped copy of its own
// (Rng::jumped()), so the extra stream is a function of the run's seed and nothing else.
#pragma once

#include <cstdint>
#include <string_view>

namespace mhb {

// FNV-1a, 64 bit (problems/core/fnv1a.hpp): stable across runs, compilers and platforms (unlike
// std::hash).
std::uint64_t stable_hash(std::string_view text) noexcept;

// SplitMix64's finaliser: a bijective mix of 64 bits.
std::uint64_t mix64(std::uint64_t x) noexcept;

// The seed of one run's stream, the same for every algorithm (common random numbers).
std::uint64_t derive_seed(std::uint64_t study_seed, std::string_view problem_spec,
                          std::uint64_t run_index) noexcept;

// The seed of one run's stream, different for each algorithm (`seeds = per-algorithm`).
std::uint64_t derive_seed(std::uint64_t study_seed, std::string_view algorithm_spec,
                          std::string_view problem_spec, std::uint64_t run_index) noexcept;

class Rng {
public:
    using result_type = std::uint64_t;

    explicit Rng(std::uint64_t seed) noexcept;

    // Raw 64 bits (xoshiro256**, Blackman and Vigna 2018). Inline: it is in every inner loop.
    result_type next() noexcept {
        const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
        const std::uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0];
        s_[3] ^= s_[1];
        s_[1] ^= s_[2];
        s_[0] ^= s_[3];
        s_[2] ^= t;
        s_[3] = rotl(s_[3], 45);
        return result;
    }
    result_type operator()() noexcept { return next(); }
    static constexpr result_type min() noexcept { return 0; }
    static constexpr result_type max() noexcept { return ~result_type{0}; }

    // Uniform on [0, 1), 53 random bits.
    double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    // Uniform on [lo, hi).
    double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * uniform(); }
    // Uniform integer on [0, n), unbiased (Lemire's multiply-and-reject). n must be > 0.
    std::uint64_t below(std::uint64_t n) noexcept;
    // Uniform index on [0, n) other than `excluded` (n must be >= 2).
    std::uint64_t below_except(std::uint64_t n, std::uint64_t excluded) noexcept;
    // Standard normal (Marsaglia's polar method; the spare value is kept for the next call).
    double normal() noexcept;
    // True with probability p.
    bool bernoulli(double p) noexcept { return uniform() < p; }

    // Advances the stream by 2^128 draws of next() (the jump() of Blackman and Vigna's reference
    // xoshiro256starstar.c): streams a jump apart never overlap in practice, so one seed yields
    // independent sub-streams. Drops a cached spare normal, which belongs to the old position.
    void jump() noexcept;
    // A copy of this stream, jumped; this stream is left as it is.
    [[nodiscard]] Rng jumped() const noexcept {
        Rng copy = *this;
        copy.jump();
        return copy;
    }

private:
    static constexpr std::uint64_t rotl(std::uint64_t x, int k) noexcept {
        return (x << k) | (x >> (64 - k));
    }

    std::uint64_t s_[4];
    double spare_normal_ = 0.0;
    bool has_spare_ = false;
};

} // namespace mhb
