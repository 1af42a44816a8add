// A population of points with their f values, and the two things every population-based baseline
// does with one: draw it uniformly in the box (through the Objective, so it is counted) and rank it.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <numeric>
#include <vector>

#include "algorithms/sampling.hpp"
#include "problems/core/rng.hpp"
#include "problems/objective.hpp"

namespace mhb {

struct Population {
    std::vector<Eigen::VectorXd> x;
    std::vector<double> f;

    [[nodiscard]] std::size_t size() const { return x.size(); }

    // Indices from best to worst; ties keep index order, so the ranking is the same everywhere.
    [[nodiscard]] std::vector<std::size_t> ranking() const {
        std::vector<std::size_t> order(f.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(),
                         [this](std::size_t a, std::size_t b) { return f[a] < f[b]; });
        return order;
    }
};

// `size` points uniform in the box, evaluated in index order (costs `size` evaluations). All are
// drawn first, then evaluated as one batch (in parallel for an expensive problem): no draw depends
// on an f, so the points, the draws and the Objective's calls are those of drawing and evaluating
// one at a time (only draws past the end of the budget differ, and the run ends there anyway).
inline Population random_population(Objective& objective, Rng& rng, std::size_t size) {
    Population p{std::vector<Eigen::VectorXd>(size), std::vector<double>(size)};
    for (std::size_t i = 0; i < size; ++i)
        p.x[i] = uniform_point(objective.bounds(), rng);
    objective.evaluate_batch(p.x, p.f);
    return p;
}

} // namespace mhb
