// How an instance number moves and turns a classic function, so that every algorithm and every
// run sees the same instance. Everything is drawn once, at construction, from our own Rng (the
// same numbers on every platform), seeded by a fixed hash of the family name, what is drawn and
// the instance number:
//
//   seed(family, purpose, instance) = mix64(mix64(stable_hash(family) ^ stable_hash(purpose)) ^ instance)
//
//   shift    (purpose "shift"): the new optimum c_i = centre_i + 0.8 half_width_i (2 u_i - 1),
//            u_i uniform in [0, 1) drawn in coordinate order, i.e. uniform in the central 80% of
//            the box, so it is always inside it with a margin of 10% of the width on each side.
//            The stream does not depend on the dimension: the shift in dimension 10 is the first
//            ten coordinates of the shift in dimension 30.
//   rotation (purpose "rotation/<dim>"): a D x D matrix of standard normals (column by column),
//            its Householder QR, Q with each column's sign set so that diag(R) > 0 (this makes Q
//            Haar-distributed; Mezzadri 2007), then the first column negated if det Q = -1, so Q is
//            a proper rotation.
//   noise    (purpose "noise"): the seed of the quartic function's noise hash.
//
// A variant evaluates f(z) with z = Q (x - c) + x*, where x* is the function's own optimum and c
// is the shifted optimum (c = x* without a shift; Q = I without a rotation): the optimum moves to
// c and f* is unchanged.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string_view>

#include "problems/problem.hpp"

namespace mhb {

std::uint64_t instance_seed(std::string_view family, std::string_view purpose,
                            std::int64_t instance) noexcept;

// The shifted optimum of `family`'s instance, inside the central 80% of `box`.
Eigen::VectorXd draw_shift(std::string_view family, std::int64_t instance, const Box& box);

// The rotation of `family`'s instance in `dimension` dimensions (orthogonal, det +1).
Eigen::MatrixXd draw_rotation(std::string_view family, std::int64_t instance, Eigen::Index dimension);

// A uniform number in [0, 1) that is a fixed function of (seed, x): SplitMix64's mix over the
// bit patterns of x's coordinates in order. Used for noise that must not be hidden state.
double hash_uniform(std::uint64_t seed, const Eigen::VectorXd& x) noexcept;

} // namespace mhb
