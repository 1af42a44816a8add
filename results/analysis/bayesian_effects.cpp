// The Bayesian reading of factorial effects (bayesian_effects.hpp).
#include "results/analysis/bayesian_effects.hpp"

#include <oneapi/tbb/parallel_for.h>

#include "problems/core/rng.hpp" // stable_hash, mix64: a test's seed from its names
#include "results/analysis/bayesian_signed_rank.hpp"

namespace mhb {

void add_bayesian_effects(std::vector<DesignEffects>& designs, double log10_rope) {
    struct Job {
        EffectEstimate* effect;
        BayesianSignedRankOptions options;
    };
    std::vector<Job> jobs;
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
                jobs.push_back({&e, options});
            }
        }
    // In parallel: each test has its own seed and writes only its own effect.
    tbb::parallel_for(std::size_t{0}, jobs.size(), [&](std::size_t i) {
        const BayesianSignedRank r = bayesian_signed_rank(jobs[i].effect->per_block, jobs[i].options);
        jobs[i].effect->p_lowers = r.left;
        jobs[i].effect->p_no_effect = r.rope;
        jobs[i].effect->p_raises = r.right;
    });
}

} // namespace mhb
