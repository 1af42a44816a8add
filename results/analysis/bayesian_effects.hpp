// The Bayesian reading of a factorial design's effects: the Bayesian signed-rank test
// (bayesian_signed_rank.hpp) of each effect's per-block estimates against 0, beside the Wilcoxon
// test of factorial_effects.hpp. Left of the ROPE = the switch on lowers the response (lower f,
// better), right = raises it. The ROPE is `log10_rope` decades on the log10(f - f*) scale; on the
// within-block rank scale no width means a practical difference, so there is no ROPE (0: only
// exact zeros are "no effect"). Each test is seeded by its design, problem and effect names.
#pragma once

#include <vector>

#include "results/analysis/factorial_effects.hpp"

namespace mhb {

// Fills p_lowers, p_no_effect and p_raises of every effect, and each analysis' rope.
void add_bayesian_effects(std::vector<DesignEffects>& designs, double log10_rope);

} // namespace mhb
