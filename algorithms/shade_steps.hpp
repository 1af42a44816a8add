// The steps L-SHADE (lshade.cpp) and jSO (jso.cpp) share: the weighted Lehmer mean of the
// success-history update, linear population size reduction (LPSR) and the binomial crossover whose
// coordinates outside the box go halfway back to the parent (JADE/SHADE's rule, so that the
// Objective's repair never acts).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "algorithms/population.hpp"
#include "problems/core/rng.hpp"
#include "problems/objective.hpp"
#include "problems/problem.hpp"

namespace mhb::shade {

// sum w s^2 / sum w s with w proportional to the improvements `delta` (SHADE's weighted Lehmer
// mean); 0 when that sum is 0.
inline double weighted_lehmer_mean(const std::vector<double>& s, const std::vector<double>& delta) {
    double num = 0.0, den = 0.0;
    for (std::size_t k = 0; k < s.size(); ++k) {
        num += delta[k] * s[k] * s[k];
        den += delta[k] * s[k];
    }
    return den > 0.0 ? num / den : 0.0;
}

// MAX_NFE, which LPSR needs: the evaluation budget, or, with only an iteration budget G, the number
// that makes LPSR reach n_min near generation G. Since dG/dNFE = 1/N(NFE) and N falls linearly,
// G = MAX_NFE ln(n_init / n_min) / (n_init - n_min), so MAX_NFE = G (n_init - n_min) / ln(n_init / n_min)
// (G n_init when the two sizes are equal).
inline double lpsr_max_evaluations(const Budget& budget, double n_init, double n_min) {
    if (budget.max_evaluations)
        return static_cast<double>(*budget.max_evaluations);
    const auto generations = static_cast<double>(*budget.max_iterations);
    if (n_init <= n_min)
        return generations * n_init;
    return generations * (n_init - n_min) / std::log(n_init / n_min);
}

// The population size LPSR plans once `nfes` evaluations are spent:
// round(n_init + (n_min - n_init) nfes / MAX_NFE), never below n_min.
inline std::size_t lpsr_size(std::size_t n_init, std::size_t n_min, double max_nfe, double nfes) {
    const double planned =
        std::round((static_cast<double>(n_min) - static_cast<double>(n_init)) / max_nfe * nfes +
                   static_cast<double>(n_init));
    return static_cast<std::size_t>(std::max(planned, static_cast<double>(n_min)));
}

// The trial vector: each coordinate from `mutant` with probability cr (one coordinate, drawn first,
// always), else from `parent`; a mutant coordinate outside the box is set halfway between the
// parent and the violated bound. Draws: the forced coordinate, then one uniform per coordinate.
inline Eigen::VectorXd binomial_crossover(const Eigen::VectorXd& parent, const Eigen::VectorXd& mutant,
                                          double cr, const Box& box, Rng& rng) {
    const Eigen::Index d = parent.size();
    const auto k_rand = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(d)));
    Eigen::VectorXd u = parent;
    for (Eigen::Index k = 0; k < d; ++k) {
        if (!(rng.uniform() < cr || k == k_rand))
            continue;
        double value = mutant[k];
        if (value < box.lower[k])
            value = 0.5 * (box.lower[k] + parent[k]);
        else if (value > box.upper[k])
            value = 0.5 * (box.upper[k] + parent[k]);
        u[k] = value;
    }
    return u;
}

// current-to-pbest/1's other two indices for target i in a population of n with an archive of
// `archive_size`: r1 uniform in the population without i, r2 uniform in population + archive
// (indices n and up are the archive's) without i and r1. Drawn in this order, r1 first.
inline std::pair<std::size_t, std::size_t> draw_r1_r2(Rng& rng, std::size_t i, std::size_t n,
                                                      std::size_t archive_size) {
    std::size_t r1 = 0;
    do {
        r1 = rng.below(n);
    } while (r1 == i);
    std::size_t r2 = 0;
    do {
        r2 = rng.below(n + archive_size);
    } while (r2 == i || r2 == r1);
    return {r1, r2};
}

// Which of several equally worst individuals goes first when the population shrinks (the authors'
// codes differ: jSO and NL-SHADE-LBC drop the first, LSHADE-cnEpSin the last).
enum class WorstTie { first, last };

// Removes the worst one by one until `n_next` remain; the survivors keep their order.
inline void remove_worst(Population& pop, std::size_t n_next, WorstTie tie) {
    while (pop.x.size() > n_next) {
        std::size_t worst = 0;
        for (std::size_t j = 1; j < pop.f.size(); ++j)
            if (pop.f[j] > pop.f[worst] || (tie == WorstTie::last && pop.f[j] == pop.f[worst]))
                worst = j;
        pop.x.erase(pop.x.begin() + static_cast<std::ptrdiff_t>(worst));
        pop.f.erase(pop.f.begin() + static_cast<std::ptrdiff_t>(worst));
    }
}

} // namespace mhb::shade
