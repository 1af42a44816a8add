// The Bayesian signed-rank test (bayesian_signed_rank.hpp): the posterior of theta sampled with
// O(n) work per sample.
#include "results/analysis/bayesian_signed_rank.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "problems/core/rng.hpp"
#include "problems/core/vector_math.hpp"

namespace mhb {

namespace {

// The mass sum_{i,j} w_i w_j [v_i + v_j < threshold] as a function of the weights, for fixed values:
// with the values sorted, the j that qualify for the k-th smallest v_i are a prefix of the sorted
// order whose length `below[k]` falls as k rises, so one pass of prefix sums per sample suffices.
struct MassBelow {
    std::vector<std::size_t> order; // indices of the values, ascending (ties by index)
    std::vector<std::size_t> below; // below[k]: how many sorted values j have v[order[k]] + v_j < threshold

    MassBelow(const std::vector<double>& values, double threshold) : order(values.size()) {
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
        below.resize(order.size());
        std::size_t count = order.size(); // falls as k rises: two pointers
        for (std::size_t k = 0; k < order.size(); ++k) {
            while (count > 0 && !(values[order[k]] + values[order[count - 1]] < threshold))
                --count;
            below[k] = count;
        }
    }

    // The mass under the weights w (indexed like the values); prefix is scratch space.
    double of(const std::vector<double>& w, std::vector<double>& prefix) const {
        prefix.resize(order.size() + 1);
        prefix[0] = 0.0;
        for (std::size_t k = 0; k < order.size(); ++k)
            prefix[k + 1] = prefix[k] + w[order[k]];
        double mass = 0.0;
        for (std::size_t k = 0; k < order.size(); ++k)
            mass += w[order[k]] * prefix[below[k]];
        return mass;
    }
};

// Gamma(shape, 1) for shape >= 1 by Marsaglia and Tsang (2000), "A simple method for generating
// gamma variables", ACM TOMS 26(3); below 1 by their boost Gamma(shape + 1) * U^(1 / shape).
double gamma_draw(double shape, Rng& rng) {
    if (shape < 1.0) {
        const double u = 1.0 - rng.uniform(); // (0, 1]
        return gamma_draw(shape + 1.0, rng) * std::pow(u, 1.0 / shape);
    }
    const double d = shape - 1.0 / 3.0;
    const double c = 1.0 / std::sqrt(9.0 * d);
    for (;;) {
        const double x = rng.normal();
        const double t = 1.0 + c * x;
        if (t <= 0.0)
            continue;
        const double v = t * t * t;
        const double u = 1.0 - rng.uniform(); // (0, 1]: log(u) finite
        if (u < 1.0 - 0.0331 * x * x * x * x || std::log(u) < 0.5 * x * x + d * (1.0 - v + std::log(v)))
            return d * v;
    }
}

// The differences with the pseudo-observation z_0 = 0 first, infinities made finite.
std::vector<double> with_prior_point(const std::vector<double>& differences) {
    constexpr double beyond_any = 1e300; // 2 x 1e300 is still finite
    std::vector<double> z = {0.0};
    for (const double d : differences) {
        if (std::isnan(d))
            throw std::invalid_argument("Bayesian signed-rank test: a difference is NaN");
        z.push_back(std::isinf(d) ? std::copysign(beyond_any, d) : d);
    }
    return z;
}

void check(const std::vector<double>& differences, const BayesianSignedRankOptions& options) {
    if (differences.empty())
        throw std::invalid_argument("Bayesian signed-rank test: no differences");
    if (!(options.rope >= 0.0) || !std::isfinite(options.rope))
        throw std::invalid_argument("Bayesian signed-rank test: the rope must be finite and >= 0");
    if (!(options.prior_strength > 0.0) || !std::isfinite(options.prior_strength))
        throw std::invalid_argument("Bayesian signed-rank test: the prior strength must be > 0");
    if (options.samples == 0)
        throw std::invalid_argument("Bayesian signed-rank test: no samples");
}

// Dirichlet(s, 1, ..., 1) draws: the prior's gamma first, then the unit weights' exponentials
// -log(U) in the order of the differences (so that the same seed gives each difference the same
// weight whatever its sign: the test's symmetry is exact).
class DirichletDraws {
public:
    DirichletDraws(std::size_t size, double prior_strength, std::uint64_t seed)
        : prior_strength_(prior_strength), rng_(seed), uniforms_(size - 1), logs_(size - 1) {}

    void next(std::vector<double>& w) {
        w[0] = gamma_draw(prior_strength_, rng_);
        for (double& u : uniforms_)
            u = 1.0 - rng_.uniform(); // (0, 1]
        vector_log(uniforms_.data(), logs_.data(), logs_.size());
        double total = w[0];
        for (std::size_t i = 0; i < logs_.size(); ++i) {
            w[i + 1] = -logs_[i];
            total += w[i + 1];
        }
        for (double& weight : w)
            weight /= total;
    }

private:
    double prior_strength_;
    Rng rng_;
    std::vector<double> uniforms_;
    std::vector<double> logs_;
};

} // namespace

BayesianSignedRank bayesian_signed_rank(const std::vector<double>& differences,
                                        const BayesianSignedRankOptions& options) {
    check(differences, options);
    const std::vector<double> z = with_prior_point(differences);
    std::vector<double> negated(z.size());
    std::transform(z.begin(), z.end(), negated.begin(), [](double v) { return -v; });
    // theta_right of z is theta_left of -z, computed by the same code: swapping x and y gives
    // bit-identical thetas in swapped places.
    const MassBelow left(z, -2.0 * options.rope);
    const MassBelow right(negated, -2.0 * options.rope);

    BayesianSignedRank out;
    out.pairs = differences.size();
    DirichletDraws draws(z.size(), options.prior_strength, options.seed);
    std::vector<double> w(z.size());
    std::vector<double> prefix;
    std::array<double, 3> wins{};
    std::array<double, 3> sums{};
    for (std::size_t s = 0; s < options.samples; ++s) {
        draws.next(w);
        const double theta_left = left.of(w, prefix);
        const double theta_right = right.of(w, prefix);
        const std::array<double, 3> theta = {theta_left, 1.0 - (theta_left + theta_right), theta_right};
        const double largest = std::max({theta[0], theta[1], theta[2]});
        const double winners = (theta[0] == largest ? 1.0 : 0.0) + (theta[1] == largest ? 1.0 : 0.0) +
                               (theta[2] == largest ? 1.0 : 0.0);
        for (std::size_t r = 0; r < 3; ++r) {
            wins[r] += theta[r] == largest ? 1.0 / winners : 0.0;
            sums[r] += theta[r];
        }
        if (s < options.kept_samples)
            out.thetas.push_back(theta);
    }
    const double n = static_cast<double>(options.samples);
    out.left = wins[0] / n;
    out.rope = wins[1] / n;
    out.right = wins[2] / n;
    for (std::size_t r = 0; r < 3; ++r)
        out.mean_theta[r] = sums[r] / n;
    return out;
}

} // namespace mhb
