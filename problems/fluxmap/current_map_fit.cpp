// The bounded multi-start Levenberg-Marquardt fit of current_map_fit.hpp.
#include "problems/fluxmap/current_map_fit.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "problems/core/rng.hpp"

namespace mhb::fluxmap {

// The step is kept inside the box so that no power of a negative exponent is taken.
Eigen::MatrixXd scaled_jacobian(const CurrentMap& map, const Box& box, const Eigen::VectorXd& theta) {
    const Eigen::Index n = theta.size();
    Eigen::VectorXd plus, minus;
    Eigen::MatrixXd j(2 * map.points(), n);
    for (Eigen::Index c = 0; c < n; ++c) {
        const double w = box.upper[c] - box.lower[c];
        const double h = 1e-6 * w;
        Eigen::VectorXd a = theta, b = theta;
        a[c] = std::min(theta[c] + h, box.upper[c]);
        b[c] = std::max(theta[c] - h, box.lower[c]);
        map.residuals(a, plus);
        map.residuals(b, minus);
        j.col(c) = (plus - minus) / ((a[c] - b[c]) / w);
    }
    return j;
}

std::vector<Eigen::VectorXd> multistart_points(const Box& box, int starts, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<Eigen::VectorXd> points;
    for (int s = 0; s < starts; ++s) {
        Eigen::VectorXd start(box.dimension());
        for (Eigen::Index c = 0; c < start.size(); ++c)
            start[c] = rng.uniform(box.lower[c], box.upper[c]);
        points.push_back(std::move(start));
    }
    return points;
}

int FitResult::reached(double relative) const {
    return static_cast<int>(std::count_if(start_f.begin(), start_f.end(),
                                          [&](double v) { return v <= f * (1 + relative) + 1e-300; }));
}

FitResult fit_from(const CurrentMap& map, const Box& box, const Eigen::VectorXd& start, int max_iterations) {
    const Eigen::VectorXd width = box.upper - box.lower;
    Eigen::VectorXd theta = start.cwiseMax(box.lower).cwiseMin(box.upper);
    Eigen::VectorXd r;
    map.residuals(theta, r);
    double f = r.squaredNorm();
    double mu = 1e-3;
    int stalled = 0;
    for (int it = 0; it < max_iterations && stalled < 10 && mu < 1e20; ++it) {
        const Eigen::MatrixXd j = scaled_jacobian(map, box, theta);
        const Eigen::MatrixXd jtj = j.transpose() * j;
        const Eigen::VectorXd g = j.transpose() * r;
        // Free coordinates: not held at a bound by a gradient that points out of the box.
        std::vector<Eigen::Index> free;
        for (Eigen::Index c = 0; c < theta.size(); ++c)
            if (!((theta[c] <= box.lower[c] && g[c] > 0) || (theta[c] >= box.upper[c] && g[c] < 0)))
                free.push_back(c);
        if (free.empty())
            break;
        const auto m = static_cast<Eigen::Index>(free.size());
        Eigen::MatrixXd a(m, m);
        Eigen::VectorXd b(m);
        for (Eigen::Index p = 0; p < m; ++p) {
            b[p] = -g[free[static_cast<std::size_t>(p)]];
            for (Eigen::Index q = 0; q < m; ++q)
                a(p, q) = jtj(free[static_cast<std::size_t>(p)], free[static_cast<std::size_t>(q)]);
        }
        while (mu < 1e20) {
            Eigen::MatrixXd damped = a;
            damped.diagonal() += mu * (a.diagonal().array() + 1e-12).matrix();
            const Eigen::VectorXd dz = damped.ldlt().solve(b);
            Eigen::VectorXd trial = theta;
            for (Eigen::Index p = 0; p < m; ++p) {
                const Eigen::Index c = free[static_cast<std::size_t>(p)];
                trial[c] = std::clamp(theta[c] + dz[p] * width[c], box.lower[c], box.upper[c]);
            }
            Eigen::VectorXd trial_r;
            map.residuals(trial, trial_r);
            const double trial_f = trial_r.squaredNorm();
            if (std::isfinite(trial_f) && trial_f < f) {
                stalled = (f - trial_f) <= 1e-15 * f ? stalled + 1 : 0;
                theta = trial, r = trial_r, f = trial_f;
                mu = std::max(mu / 3, 1e-15);
                break;
            }
            mu *= 4;
        }
    }
    FitResult result;
    result.theta = theta;
    result.f = f;
    result.start_f = {f};
    return result;
}

FitResult fit_multistart(const CurrentMap& map, const Box& box, const FitOptions& options) {
    FitResult best;
    best.f = std::numeric_limits<double>::infinity();
    for (const Eigen::VectorXd& start : multistart_points(box, options.starts, options.seed)) {
        const FitResult one = fit_from(map, box, start, options.max_iterations);
        best.start_f.push_back(one.f);
        if (one.f < best.f)
            best.theta = one.theta, best.f = one.f;
    }
    return best;
}

} // namespace mhb::fluxmap
