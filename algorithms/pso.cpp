// PSO with the settings of Li, Wang, Ji (2017), section 4.1: global-best particle swarm
// optimisation (J. Kennedy, R. Eberhart (1995), "Particle swarm optimization", Proc. ICNN 4:
// 1942-1948) with the inertia weight of Y. Shi, R. Eberhart (1998), "A modified particle swarm
// optimizer", Proc. IEEE ICEC: 69-73:
//   v_i <- w v_i + c1 r1 (pbest_i - x_i) + c2 r2 (gbest - x_i),   x_i <- x_i + v_i,
// r1, r2 uniform on [0, 1). Defaults w = 0.5, c1 = c2 = 2 and NP = 50 are the paper's.
// These sit on the edge of PSO's order-2 stability region (c1 + c2 < 24 (1 - w^2) / (7 - 5 w),
// Poli 2009, which is 4 at w = 0.5), which alone explains much of its spread in the paper.
// Evaluations: NP to initialise, then NP per iteration.
//
// The paper gives nothing beyond w, c1, c2 and NP; our choices, each the plainest one:
//   - initial positions uniform in the box (as eq. 5 for TLBO); initial velocities zero
//     (A. Engelbrecht (2012), "Particle swarm optimization: Velocity initialization", IEEE CEC,
//     recommends zero or small random initial velocities: large random ones send particles out
//     of the box in the first iterations). From zero velocity the first move of each particle
//     is towards the global best only;
//   - positions are clamped to the box (the Objective's clamp policy, "clamp to bounds" in
//     ARCHITECTURE.md section 9); the velocity is left as it is;
//   - no velocity clamp by default (vmax = 0); vmax > 0 limits each velocity component to
//     vmax times the box's width in that coordinate;
//   - synchronous global best: gbest is updated once per iteration, after every particle has
//     moved and been evaluated (particles read the gbest of the previous iteration);
//   - pbest_i is replaced only by a strictly better point.
//
// r1 and r2, parameter `r`:
//   coordinate (default)  a fresh r1 and r2 for every coordinate (the usual coding, and every
//                         result before `r` existed);
//   learner               one r1 and one r2 per particle and move, used for every coordinate.
// The paper gives no PSO equation, only w, c1, c2 and NP. With one pair per particle the velocity
// update is a combination of the vectors v, pbest - x and gbest - x, so PSO becomes rotation-
// invariant (apart from the initial box and clamping), but the swarm can collapse onto the
// subspace those vectors span (D. N. Wilke, S. Kok, A. A. Groenwold (2007), "Comparison of linear
// and classical velocity update rules in particle swarm optimization: notes on diversity", IJNME
// 69(8), compare the two); per coordinate the step leaves that subspace, leans towards the axes
// and favours separable functions (tlbo.cpp's header says the same of TLBO's r).
// Measured: on the 10-D sphere, 400 iterations, 20 seeds, the worst run ends at 2e-18 with
// r=coordinate and at 11 with r=learner (the paper's w = 0.5, c1 = c2 = 2), likely that loss of
// diversity; we have not analysed it further.
// Random draws, in order: initial positions (particle by particle, coordinate by coordinate);
// per particle move, r1 then r2 for each coordinate (coordinate), or r1 then r2 once (learner).
#include <algorithm>
#include <span>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/population_limits.hpp"
#include "algorithms/sampling.hpp"

namespace mhb {
namespace {

struct PsoSettings {
    Eigen::Index np = 50;
    double w = 0.5;
    double c1 = 2.0;
    double c2 = 2.0;
    double vmax = 0.0;           // fraction of the box width; 0: no velocity clamp
    bool per_particle_r = false; // r=learner: one r1 and one r2 per particle and move
};

class Pso final : public Optimizer {
public:
    explicit Pso(PsoSettings settings) : s_(settings) {}

    std::string name() const override { return "pso"; }

    // The positions, velocities, personal bests and the batch of new points.
    std::optional<std::string> refusal(Eigen::Index dimension) const override {
        return population_memory_refusal("pso", 4.0 * static_cast<double>(s_.np), dimension, "np");
    }

    void run(Objective& objective, Rng& rng) const override {
        const Eigen::Index d = objective.dimension();
        const Box& box = objective.bounds();
        Eigen::MatrixXd x(d, s_.np);
        Eigen::MatrixXd v = Eigen::MatrixXd::Zero(d, s_.np);
        Eigen::MatrixXd pbest(d, s_.np);
        Eigen::VectorXd pbest_f(s_.np);
        // Particles are independent within an iteration (gbest is synchronous, below), so each
        // iteration's NP positions are computed first and evaluated as one batch (in parallel for
        // an expensive problem) in particle order: the same draws and evaluations as one by one.
        const auto np = static_cast<std::size_t>(s_.np);
        std::vector<Eigen::VectorXd> points(np);
        std::vector<double> f(np);
        for (auto& point : points)
            point = uniform_point(box, rng);
        objective.evaluate_batch(points, std::span<double>(pbest_f.data(), np));
        for (Eigen::Index i = 0; i < s_.np; ++i)
            x.col(i) = points[static_cast<std::size_t>(i)];
        pbest = x;
        objective.initialised();

        const Eigen::VectorXd vmax = s_.vmax * (box.upper - box.lower);
        Eigen::VectorXd gbest = pbest.col(best_index(pbest_f));
        while (!objective.exhausted()) {
            for (Eigen::Index i = 0; i < s_.np; ++i) {
                // r=learner draws the pair once here; r=coordinate draws it again for each k.
                double r1 = 0.0;
                double r2 = 0.0;
                if (s_.per_particle_r) {
                    r1 = rng.uniform();
                    r2 = rng.uniform();
                }
                Eigen::VectorXd& point = points[static_cast<std::size_t>(i)];
                for (Eigen::Index k = 0; k < d; ++k) {
                    if (!s_.per_particle_r) {
                        r1 = rng.uniform();
                        r2 = rng.uniform();
                    }
                    double vk = s_.w * v(k, i) + s_.c1 * r1 * (pbest(k, i) - x(k, i)) +
                                s_.c2 * r2 * (gbest[k] - x(k, i));
                    if (s_.vmax > 0.0)
                        vk = std::clamp(vk, -vmax[k], vmax[k]);
                    v(k, i) = vk;
                    point[k] = x(k, i) + vk;
                }
            }
            objective.evaluate_batch(points, f); // clamps each point to the box
            for (Eigen::Index i = 0; i < s_.np; ++i) {
                const auto j = static_cast<std::size_t>(i);
                x.col(i) = points[j];
                if (f[j] < pbest_f[i]) {
                    pbest_f[i] = f[j];
                    pbest.col(i) = points[j];
                }
            }
            gbest = pbest.col(best_index(pbest_f));
            objective.end_iteration();
        }
    }

private:
    // Lowest index among equals, so that ties never depend on anything but the values.
    static Eigen::Index best_index(const Eigen::VectorXd& f) {
        Eigen::Index best = 0;
        for (Eigen::Index i = 1; i < f.size(); ++i)
            if (f[i] < f[best])
                best = i;
        return best;
    }

    PsoSettings s_;
};

} // namespace

void register_pso(AlgorithmRegistry& registry) {
    registry.add(
        {"pso",
         1,
         "global-best particle swarm optimisation with inertia weight, the settings of Li, Wang, Ji "
         "(2017); NP evaluations per iteration",
         "Kennedy, Eberhart (1995), Proc. ICNN 4:1942-1948; inertia weight: Shi, Eberhart (1998), "
         "Proc. IEEE ICEC:69-73",
         {ParameterInfo::integer("np", 50, 2, 100000,
                                 "swarm size; 50 as in Li, Wang, Ji (2017), section 4.1"),
          ParameterInfo::real("w", 0.5, 0.0, 1.0, "inertia weight; 0.5 as in Li, Wang, Ji (2017)"),
          ParameterInfo::real("c1", 2.0, 0.0, 4.0, "cognitive coefficient; 2 as in Li, Wang, Ji (2017)"),
          ParameterInfo::real("c2", 2.0, 0.0, 4.0, "social coefficient; 2 as in Li, Wang, Ji (2017)"),
          ParameterInfo::real(
              "vmax", 0.0, 0.0, 1.0,
              "velocity clamp as a fraction of the box width; 0: none (the paper gives none)"),
          ParameterInfo::choice("r", "coordinate", {"coordinate", "learner"},
                                "r1, r2 drawn per coordinate (default; favours separable functions) or "
                                "once per particle and move for every coordinate (rotation-invariant)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             PsoSettings s;
             s.np = static_cast<Eigen::Index>(p.integer("np"));
             s.w = p.real("w");
             s.c1 = p.real("c1");
             s.c2 = p.real("c2");
             s.vmax = p.real("vmax");
             s.per_particle_r = p.text("r") == "learner";
             return std::make_unique<Pso>(s);
         }},
        {"PSO"});
}

} // namespace mhb
