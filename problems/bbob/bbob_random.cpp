#include "problems/bbob/bbob_random.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mhb::bbob {
namespace {

// One step of Park and Miller's generator, x <- 16807 x mod (2^31 - 1), by Schrage's method
// (the integer division is done through double floor, as the legacy code does).
std::int64_t park_miller(std::int64_t seed) {
    const auto q = static_cast<std::int64_t>(std::floor(static_cast<double>(seed) / 127773.0));
    seed = 16807 * (seed - q * 127773) - 2836 * q;
    return seed < 0 ? seed + 2147483647 : seed;
}

} // namespace

std::vector<double> legacy_uniform(std::size_t n, std::int64_t seed) {
    if (seed < 0)
        seed = -seed;
    if (seed < 1)
        seed = 1;
    // Warm up for 8 steps, then fill the 32-entry shuffle table (Bays-Durham shuffle).
    std::int64_t table[32];
    for (int i = 39; i >= 0; --i) {
        seed = park_miller(seed);
        if (i < 32)
            table[i] = seed;
    }
    std::int64_t last = table[0];
    std::vector<double> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        seed = park_miller(seed);
        const auto slot = static_cast<std::size_t>(std::floor(static_cast<double>(last) / 67108865.0));
        last = table[slot];
        table[slot] = seed;
        out[i] = static_cast<double>(last) / 2.147483647e9;
        if (out[i] == 0.0)
            out[i] = 1e-99;
    }
    return out;
}

std::vector<double> legacy_gauss(std::size_t n, std::int64_t seed) {
    const std::vector<double> u = legacy_uniform(2 * n, seed);
    std::vector<double> g(n);
    for (std::size_t i = 0; i < n; ++i) {
        g[i] = std::sqrt(-2.0 * std::log(u[i])) * std::cos(2.0 * std::numbers::pi * u[n + i]);
        if (g[i] == 0.0)
            g[i] = 1e-99;
    }
    return g;
}

Eigen::MatrixXd legacy_rotation(std::int64_t seed, Eigen::Index dimension) {
    const auto d = static_cast<std::size_t>(dimension);
    const std::vector<double> g = legacy_gauss(d * d, seed);
    // Column-major fill: B(i, j) = g[j d + i].
    Eigen::MatrixXd b(dimension, dimension);
    for (Eigen::Index j = 0; j < dimension; ++j)
        for (Eigen::Index i = 0; i < dimension; ++i)
            b(i, j) = g[static_cast<std::size_t>(j) * d + static_cast<std::size_t>(i)];
    // Modified Gram-Schmidt over the columns, in the legacy order of operations, so that the
    // matrix matches COCO's to the last bits.
    for (Eigen::Index i = 0; i < dimension; ++i) {
        for (Eigen::Index j = 0; j < i; ++j) {
            double prod = 0.0;
            for (Eigen::Index k = 0; k < dimension; ++k)
                prod += b(k, i) * b(k, j);
            for (Eigen::Index k = 0; k < dimension; ++k)
                b(k, i) -= prod * b(k, j);
        }
        double prod = 0.0;
        for (Eigen::Index k = 0; k < dimension; ++k)
            prod += b(k, i) * b(k, i);
        for (Eigen::Index k = 0; k < dimension; ++k)
            b(k, i) /= std::sqrt(prod);
    }
    return b;
}

Eigen::VectorXd legacy_xopt(std::int64_t seed, Eigen::Index dimension) {
    const std::vector<double> u = legacy_uniform(static_cast<std::size_t>(dimension), seed);
    Eigen::VectorXd x(dimension);
    for (Eigen::Index i = 0; i < dimension; ++i) {
        x[i] = 8.0 * std::floor(1e4 * u[static_cast<std::size_t>(i)]) / 1e4 - 4.0;
        if (x[i] == 0.0)
            x[i] = -1e-5;
    }
    return x;
}

double legacy_fopt(int function, std::int64_t instance) {
    const std::int64_t base = function == 4 ? 3 : function == 18 ? 17 : function;
    const std::int64_t seed = base + 10000 * instance;
    const double numerator = legacy_gauss(1, seed)[0];
    const double denominator = legacy_gauss(1, seed + 1)[0];
    const double rounded = std::floor(100.0 * 100.0 * numerator / denominator + 0.5) / 100.0;
    return std::min(1000.0, std::max(-1000.0, rounded));
}

std::int64_t instance_seed(int function, std::int64_t instance) {
    const std::int64_t base = function == 4 ? 3 : function == 18 ? 17 : function;
    return base + 10000 * instance;
}

} // namespace mhb::bbob
