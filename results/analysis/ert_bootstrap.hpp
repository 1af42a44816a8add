// ERT with COCO's bootstrap of simulated restarts (cocopp's toolsstats.drawSP): how far the
// evaluations to a target spread when an algorithm is restarted until it succeeds.
//
// One simulated run length: draw runs uniformly with replacement from all runs of the group,
// adding the evaluations of each unsuccessful one drawn (all it spent), until a successful one is
// drawn, whose evaluations to the target are added last. Its mean is the ERT (statistics.hpp);
// COCO's tables give the 10th and 90th percentiles of `samples` such lengths (cocopp's default
// simulated_runlength_bootstrap_sample_size, 1000) as the ERT's dispersion, with cocopp's
// prctile (below). The draws come from an mhb::Rng seeded by the caller, so a report is the same
// every time it is made.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "problems/core/rng.hpp" // the one random stream every part of mhbench draws from
#include "results/analysis/statistics.hpp"

namespace mhb {

// cocopp's simulated_runlength_bootstrap_sample_size when not in a hurry.
inline constexpr std::size_t ert_bootstrap_samples = 1000;

// `samples` simulated run lengths, sorted; empty when no run succeeded (the ERT is infinite).
std::vector<double> simulated_run_lengths(const std::vector<TargetHit>& runs, std::size_t samples, Rng& rng);

// cocopp's prctile: the p-th percentile (0..100) of a sorted sample, i = p/100 N - 0.5 (0-based),
// linear between the neighbours, the extremes outside. Not R's type 7 (statistics.hpp): COCO's.
double coco_percentile(const std::vector<double>& sorted, double p);

struct ErtInterval {
    double ert = 0.0;
    double p10 = 0.0; // the 10th and 90th percentiles of the simulated run lengths
    double p90 = 0.0;
};

// The ERT and its bootstrap percentiles; nullopt when no run succeeded.
std::optional<ErtInterval> ert_interval(const std::vector<TargetHit>& runs, Rng& rng,
                                        std::size_t samples = ert_bootstrap_samples);

} // namespace mhb
