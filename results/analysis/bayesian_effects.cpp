// The Bayesian reading of factorial effects (bayesian_effects.hpp).
#include "results/analysis/bayesian_effects.hpp"

#include "problems/core/rng.hpp" // stable_hash, mix64: a test's seed from its names
#include "results/analysis/bayesian_signed_rank.hpp"

namespace mhb {

void add_bayesian_effects(std::vector<DesignEffects>& designs, double log10_rope) {
    for (auto& d : designs)
        for (auto& a : d.analyses) {
            if (a.scale == ResponseScale::log10_gap)
                a.rope = log10_rope;
            for (auto& e : a.effects) {
                if (e.per_block.empty())
                    continue;
                BayesianSignedRankOptions options;
                options.rope = a.rope.value_or(0.0);
                options.seed = mix64(stable_hash(d.design.description() + '\n' + a.problem + '\n' + e.name));
                const BayesianSignedRank r = bayesian_signed_rank(e.per_block, options);
                e.p_lowers = r.left;
                e.p_no_effect = r.rope;
                e.p_raises = r.right;
            }
        }
}

} // namespace mhb
