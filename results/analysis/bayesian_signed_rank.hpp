// The Bayesian signed-rank test with a region of practical equivalence (ROPE), as Benavoli, Corani,
// Demsar and Zaffalon define it ("Time for a change", JMLR 18(77), 2017, section 4; Benavoli et
// al., ICML 2014) and as baycomp's SignedRankTest and scmamp's bSignedRankTest compute it.
//
// Data: differences z_1..z_n of paired values, z_i = x_i - y_i. With minimised values (f, or the
// log10 gap to f*), a negative difference means x is better. Sign convention, kept everywhere:
//   left  = z < -rope: the FIRST sample (x) is better (lower) by more than the rope,
//   rope  = -rope <= z <= rope: practically equivalent,
//   right = z > +rope: the SECOND sample (y) is better.
// Model: a Dirichlet process prior of strength s = 0.5 centred on one pseudo-observation z_0 = 0
// (inside the rope: the prior leans to "no practical difference"). Its posterior weights are
// w ~ Dirichlet(s, 1, ..., 1) over (z_0, z_1, ..., z_n), and
//   theta_left  = sum_{i,j} w_i w_j [z_i + z_j < -2 rope],
//   theta_right = sum_{i,j} w_i w_j [z_i + z_j > +2 rope],
//   theta_rope  = 1 - theta_left - theta_right,
// the i, j running over every ordered pair, the pseudo-observation included, i = j too: the Walsh
// averages (z_i + z_j) / 2 of the signed-rank test, a pair i < j weighing 2 w_i w_j. The rope's
// bounds belong to the rope (scmamp; baycomp gives a sum exactly on a bound half to each side).
// P(left), P(rope), P(right): the fraction of Monte Carlo samples of theta in which that region's
// theta is the largest; a tie of two (or three) largest shares the sample equally (scmamp and the
// authors' R tutorial; baycomp's argmax gives it to the first). Sharing makes the test exactly
// symmetric: swapping x and y swaps P(left) and P(right).
// Samples: 50 000 by default, baycomp's default (scmamp's is 1000, too few for two decimals);
// the Monte Carlo standard error of a probability is then at most 0.0022.
//
// Reproducible: the weights are drawn from mhb::Rng (the given seed) with our own gamma draws
// (exponential for the unit weights, Marsaglia and Tsang 2000 for the prior's), and the
// logarithms of the exponentials come from vector_log (plain IEEE operations), so the same
// differences, rope and seed give the same probabilities on every platform.
// Fast: the thresholds of the Walsh sums depend on the data alone, so the differences are sorted
// once and each sample costs O(n) (prefix sums of the weights), not O(n^2): 50 000 samples of
// 300 differences take well under a second (tests/bench/bayesian_signed_rank_bench.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mhb {

// Benavoli et al. 2017's prior: strength s at z_0 = 0.
inline constexpr double bayesian_prior_strength = 0.5;
// baycomp's default number of posterior samples.
inline constexpr std::size_t bayesian_default_samples = 50000;

struct BayesianSignedRankOptions {
    double rope = 0.0; // half-width of the ROPE, >= 0, in the units of the differences
    std::size_t samples = bayesian_default_samples;
    std::uint64_t seed = 1;
    double prior_strength = bayesian_prior_strength;
    std::size_t kept_samples = 0; // how many theta samples to return (the first ones), for figures
};

struct BayesianSignedRank {
    double left = 0.0;                         // P(theta_left is the largest): x better
    double rope = 0.0;                         // P(theta_rope is the largest): practically equivalent
    double right = 0.0;                        // P(theta_right is the largest): y better
    std::array<double, 3> mean_theta{};        // posterior means of (theta_left, theta_rope, theta_right)
    std::size_t pairs = 0;                     // n, the differences (the pseudo-observation not counted)
    std::vector<std::array<double, 3>> thetas; // the first kept_samples samples of theta
};

// The test of `differences` (z_i = x_i - y_i). An infinite difference (a run that ended at +inf
// against one that did not) is read as +-1e300, beyond any other, so that its Walsh average with
// an opposite infinity is 0 rather than NaN. Throws std::invalid_argument for no differences, a
// NaN difference, a rope that is negative or not finite, a prior strength <= 0 or no samples.
BayesianSignedRank bayesian_signed_rank(const std::vector<double>& differences,
                                        const BayesianSignedRankOptions& options);

} // namespace mhb
