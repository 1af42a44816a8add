// CEC 2022's U-score of the algorithms on one function (cec_tables.hpp): every trial ranked
// together, worst first, and each algorithm's rank sum less its least possible.
#include <algorithm>

#include "results/tables/cec_tables.hpp"

namespace mhb {

std::vector<double> cec_u_scores(const std::vector<std::vector<CecTrial>>& trials) {
    // Every trial, worst first: not reached before reached; among those not reached, the larger error
    // first; among those reached, the later FEterm first. Rank 1 = the worst, so the best trial gets
    // the highest rank (n m when no trial failed), as the TR assigns them.
    struct Entry {
        std::size_t algorithm;
        const CecTrial* trial;
    };
    std::vector<Entry> all;
    for (std::size_t j = 0; j < trials.size(); ++j)
        for (const auto& t : trials[j])
            all.push_back({j, &t});
    const auto worse = [](const CecTrial& a, const CecTrial& b) { // a ranks below b
        if (a.reached != b.reached)
            return !a.reached;
        if (!a.reached)
            return a.error > b.error;
        return a.termination > b.termination;
    };
    std::stable_sort(all.begin(), all.end(),
                     [&](const Entry& a, const Entry& b) { return worse(*a.trial, *b.trial); });
    std::vector<double> scores(trials.size(), 0.0);
    for (std::size_t i = 0; i < all.size();) {
        std::size_t end = i + 1;
        while (end < all.size() && !worse(*all[i].trial, *all[end].trial))
            ++end;
        const double rank = (static_cast<double>(i + 1) + static_cast<double>(end)) / 2.0; // ties: mean rank
        for (std::size_t k = i; k < end; ++k)
            scores[all[k].algorithm] += rank;
        i = end;
    }
    for (std::size_t j = 0; j < trials.size(); ++j) {
        const auto n = static_cast<double>(trials[j].size());
        scores[j] -= n * (n + 1.0) / 2.0;
    }
    return scores;
}

} // namespace mhb
