// Standard PSO 2011 (M. Clerc, "Standard Particle Swarm Optimisation", 2011/2012 description of
// SPSO 2011, hal-00764996; Zambrano-Bigiarini, Clerc and Rojas, IEEE CEC 2013). The modern PSO
// baseline beside the paper's PSO (w = 0.5, c1 = c2 = 2), which sits at the edge of stability.
//
// - Swarm S = 40; w = 1/(2 ln 2) ~ 0.721, c = 1/2 + ln 2 ~ 1.193 (Clerc's constants).
// - Adaptive random topology: each particle informs itself and K = 3 particles drawn at random
//   (with repetition); the links are redrawn after an iteration that did not improve the best.
// - Move: with p the particle's best and l the best of its informants, p' = x + c U (p - x) and
//   l' = x + c U (l - x) (U uniform on [0, 1], drawn per coordinate); the centre of gravity is
//   G = (x + p' + l') / 3, or (x + p') / 2 when the particle is its own best informant; x' is
//   uniform in the ball of centre G and radius |G - x|; v <- w v + x' - x; x <- x + v.
// - Confinement: a coordinate that leaves the box is put on the bound and its velocity becomes
//   -0.5 v (SPSO 2011's rule), so the Objective's repair never acts.
// - Initialisation: x uniform in the box, v_k uniform in [lower_k - x_k, upper_k - x_k].
// Particles move asynchronously (each sees its informants' latest bests) in a fresh random order
// every iteration, as in Clerc's reference code.
// Evaluations: S to initialise, then S per iteration.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/population_limits.hpp"
#include "algorithms/sampling.hpp"

namespace mhb {
namespace {

class Spso2011 final : public Optimizer {
public:
    Spso2011(long long swarm, long long informants, double w, double c)
        : swarm_(swarm), informants_(informants), w_(w), c_(c) {}

    std::string name() const override { return "spso2011"; }

    // Positions, velocities, personal bests and the batch of new points.
    std::optional<std::string> refusal(Eigen::Index dimension) const override {
        return population_memory_refusal("spso2011", 4.0 * static_cast<double>(swarm_), dimension, "S");
    }

    void run(Objective& objective, Rng& rng) const override {
        const Eigen::Index d = objective.dimension();
        const Box& box = objective.bounds();
        const auto s = static_cast<std::size_t>(swarm_);
        std::vector<Eigen::VectorXd> x(s), v(s), p(s);
        std::vector<double> fp(s);
        // The initial swarm is drawn first and evaluated as one batch (in parallel for an
        // expensive problem): no draw depends on an f. The moves below are asynchronous (each
        // particle sees the bests its informants have just found), so they are evaluated one by one.
        for (std::size_t i = 0; i < s; ++i) {
            x[i] = uniform_point(box, rng);
            v[i].resize(d);
            for (Eigen::Index k = 0; k < d; ++k)
                v[i][k] = rng.uniform(box.lower[k] - x[i][k], box.upper[k] - x[i][k]);
        }
        objective.evaluate_batch(x, fp);
        p = x;
        objective.initialised();

        // informed_by[i][j]: particle j informs particle i.
        std::vector<std::vector<char>> informed_by(s, std::vector<char>(s, 0));
        const auto draw_links = [&] {
            for (auto& row : informed_by)
                std::fill(row.begin(), row.end(), char{0});
            for (std::size_t j = 0; j < s; ++j) {
                informed_by[j][j] = 1;
                for (long long k = 0; k < informants_; ++k)
                    informed_by[rng.below(s)][j] = 1;
            }
        };
        draw_links();

        std::vector<std::size_t> order(s);
        Eigen::VectorXd g(d), direction(d), target(d);
        double best_before = best_of(fp);
        while (!objective.exhausted()) {
            std::iota(order.begin(), order.end(), std::size_t{0});
            for (std::size_t i = s; i > 1; --i) // Fisher-Yates
                std::swap(order[i - 1], order[rng.below(i)]);
            for (const std::size_t i : order) {
                std::size_t l = i;
                for (std::size_t j = 0; j < s; ++j)
                    if (informed_by[i][j] && fp[j] < fp[l])
                        l = j;
                // p' = x + c U(0,1) (p - x) and l' = x + c U(0,1) (l - x), one U per coordinate.
                for (Eigen::Index k = 0; k < d; ++k) {
                    const double to_p = c_ * rng.uniform() * (p[i][k] - x[i][k]);
                    if (l != i)
                        g[k] = x[i][k] + (to_p + c_ * rng.uniform() * (p[l][k] - x[i][k])) / 3.0;
                    else
                        g[k] = x[i][k] + to_p / 2.0;
                }
                // Uniform in the ball: a Gaussian direction and a radius |G - x| * U^(1/D).
                const double radius =
                    (g - x[i]).norm() * std::pow(rng.uniform(), 1.0 / static_cast<double>(d));
                for (Eigen::Index k = 0; k < d; ++k)
                    direction[k] = rng.normal();
                const double dir_norm = direction.norm();
                target = dir_norm > 0.0 ? Eigen::VectorXd(g + radius / dir_norm * direction) : g;
                v[i] = w_ * v[i] + target - x[i];
                x[i] += v[i];
                for (Eigen::Index k = 0; k < d; ++k) {
                    if (x[i][k] < box.lower[k]) {
                        x[i][k] = box.lower[k];
                        v[i][k] *= -0.5;
                    } else if (x[i][k] > box.upper[k]) {
                        x[i][k] = box.upper[k];
                        v[i][k] *= -0.5;
                    }
                }
                const double f = objective.evaluate(x[i]);
                if (f < fp[i]) {
                    fp[i] = f;
                    p[i] = x[i];
                }
            }
            const double best_now = best_of(fp);
            if (!(best_now < best_before))
                draw_links();
            best_before = best_now;
            objective.end_iteration();
        }
    }

private:
    static double best_of(const std::vector<double>& f) { return *std::min_element(f.begin(), f.end()); }

    long long swarm_;
    long long informants_;
    double w_;
    double c_;
};

} // namespace

void register_spso2011(AlgorithmRegistry& registry) {
    registry.add(
        {"spso2011",
         1,
         "Standard PSO 2011: adaptive random topology (K = 3), hypersphere sampling around G; "
         "S evaluations per iteration",
         "Clerc (2012), Standard Particle Swarm Optimisation, hal-00764996; Zambrano-Bigiarini et al. "
         "(2013), IEEE CEC 2013",
         {ParameterInfo::integer("S", 40, 2, 1000000, "swarm size (SPSO 2011: 40)"),
          ParameterInfo::integer("K", 3, 1, 1000, "informants drawn per particle (SPSO 2011: 3)"),
          ParameterInfo::real("w", 1.0 / (2.0 * std::numbers::ln2), 0.0, 1.0,
                              "inertia weight (SPSO 2011: 1/(2 ln 2))"),
          ParameterInfo::real("c", 0.5 + std::numbers::ln2, 0.0, 10.0,
                              "acceleration coefficient (SPSO 2011: 1/2 + ln 2)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             return std::make_unique<Spso2011>(p.integer("S"), p.integer("K"), p.real("w"), p.real("c"));
         }},
        {"SPSO 2011"});
}

} // namespace mhb
