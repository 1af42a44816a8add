// L-SHADE (Tanabe and Fukunaga 2014, "Improving the search performance of SHADE using linear
// population size reduction", IEEE CEC 2014): DE with current-to-pbest/1/bin, success-history
// adaptation of F and CR (H memory slots, weighted Lehmer means), an external archive of replaced
// parents, and linear population size reduction (LPSR) from N_init to N_min.
//
// Defaults are the paper's: N_init = round(18 D), N_min = 4, |A| = round(2.6 N), p = 0.11, H = 6,
// memories start at 0.5. F_i ~ Cauchy(M_F, 0.1) (regenerated while <= 0, cut at 1); CR_i ~
// N(M_CR, 0.1) clipped to [0, 1], and 0 once a CR memory slot is terminal. A mutant coordinate that
// leaves the box is set halfway between the parent and the violated bound (JADE/SHADE's rule), so
// the Objective's repair never acts.
//
// LPSR needs the maximum number of evaluations. With an evaluation budget that is it. With only an
// iteration budget G, it is derived so that LPSR reaches N_min near generation G: since
// dG/dNFE = 1/N(NFE) and N falls linearly, G = MAX_NFE ln(N_init/N_min) / (N_init - N_min), so
// MAX_NFE = G (N_init - N_min) / ln(N_init/N_min) (N_init when the two sizes are equal).
// Evaluations: N_init to initialise, then the current population size N_G per iteration.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/population.hpp"
#include "algorithms/shade_steps.hpp"

namespace mhb {
namespace {

struct LshadeSettings {
    double r_ninit = 18.0;
    long long n_min = 4;
    double r_arc = 2.6;
    double p_best = 0.11;
    long long memory = 6;
};

class Lshade final : public Optimizer {
public:
    explicit Lshade(LshadeSettings settings) : s_(settings) {}

    std::string name() const override { return "lshade"; }

    void run(Objective& objective, Rng& rng) const override {
        const Eigen::Index d = objective.dimension();
        const Box& box = objective.bounds();
        const auto n_init = static_cast<std::size_t>(std::llround(s_.r_ninit * static_cast<double>(d)));
        const auto n_min = static_cast<std::size_t>(s_.n_min);
        if (n_init < n_min)
            throw std::invalid_argument(
                "lshade: initial population round(r_ninit * D) = " + std::to_string(n_init) +
                " is smaller than n_min = " + std::to_string(n_min) +
                "; raise 'r_ninit' (the population is too small)");
        const double max_nfe = shade::lpsr_max_evaluations(objective.budget(), static_cast<double>(n_init),
                                                           static_cast<double>(n_min));

        Population pop = random_population(objective, rng, n_init);
        auto& x = pop.x;
        auto& fx = pop.f;
        objective.initialised();

        const auto h = static_cast<std::size_t>(s_.memory);
        std::vector<double> m_cr(h, 0.5), m_f(h, 0.5);
        std::vector<bool> cr_terminal(h, false);
        std::size_t k_memory = 0;
        std::vector<Eigen::VectorXd> archive;
        std::size_t archive_max =
            static_cast<std::size_t>(std::llround(s_.r_arc * static_cast<double>(n_init)));

        std::vector<Eigen::VectorXd> trials;
        std::vector<double> f_trials, cr_used, f_used, s_cr, s_f, s_delta;
        std::vector<std::size_t> order;
        Eigen::VectorXd v(d);
        while (!objective.exhausted()) {
            const std::size_t n = x.size();
            order = pop.ranking();
            const std::size_t n_pbest = std::max<std::size_t>(
                2, static_cast<std::size_t>(std::llround(s_.p_best * static_cast<double>(n))));

            trials.assign(n, Eigen::VectorXd());
            f_trials.assign(n, 0.0);
            cr_used.assign(n, 0.0);
            f_used.assign(n, 0.0);
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t r = rng.below(h);
                cr_used[i] = cr_terminal[r] ? 0.0 : std::clamp(m_cr[r] + 0.1 * rng.normal(), 0.0, 1.0);
                double f = 0.0;
                do {
                    f = m_f[r] + 0.1 * std::tan(std::numbers::pi * (rng.uniform() - 0.5));
                } while (f <= 0.0);
                f_used[i] = std::min(f, 1.0);

                const Eigen::VectorXd& pbest = x[order[rng.below(n_pbest)]];
                std::size_t r1 = 0;
                do {
                    r1 = rng.below(n);
                } while (r1 == i);
                std::size_t r2 = 0;
                do {
                    r2 = rng.below(n + archive.size());
                } while (r2 == i || r2 == r1);
                const Eigen::VectorXd& x_r2 = r2 < n ? x[r2] : archive[r2 - n];

                const double fi = f_used[i];
                v = x[i] + fi * (pbest - x[i]) + fi * (x[r1] - x_r2);
                trials[i] = shade::binomial_crossover(x[i], v, cr_used[i], box, rng);
            }
            // Every trial is built from the generation as it began, so they are evaluated as one
            // batch (in parallel for an expensive problem), in index order, before any selection.
            objective.evaluate_batch(trials, f_trials);

            // Selection, archive and the successful parameters.
            s_cr.clear();
            s_f.clear();
            s_delta.clear();
            for (std::size_t i = 0; i < n; ++i) {
                if (f_trials[i] > fx[i])
                    continue;
                if (f_trials[i] < fx[i]) {
                    if (archive_max > 0) {
                        if (archive.size() < archive_max)
                            archive.push_back(x[i]);
                        else
                            archive[rng.below(archive.size())] = x[i];
                    }
                    s_cr.push_back(cr_used[i]);
                    s_f.push_back(f_used[i]);
                    s_delta.push_back(fx[i] - f_trials[i]);
                }
                x[i] = std::move(trials[i]);
                fx[i] = f_trials[i];
            }
            if (!s_f.empty()) {
                const bool all_cr_zero = *std::max_element(s_cr.begin(), s_cr.end()) == 0.0;
                if (cr_terminal[k_memory] || all_cr_zero)
                    cr_terminal[k_memory] = true;
                else
                    m_cr[k_memory] = shade::weighted_lehmer_mean(s_cr, s_delta);
                m_f[k_memory] = shade::weighted_lehmer_mean(s_f, s_delta);
                k_memory = (k_memory + 1) % h;
            }

            // Linear population size reduction: drop the worst, shrink the archive at random.
            const std::size_t n_next =
                shade::lpsr_size(n_init, n_min, max_nfe, static_cast<double>(objective.evaluations()));
            if (n_next < n) {
                order = pop.ranking();
                std::vector<Eigen::VectorXd> kept_x(n_next);
                std::vector<double> kept_f(n_next);
                std::sort(order.begin(),
                          order.begin() + static_cast<std::ptrdiff_t>(n_next)); // keep index order
                for (std::size_t j = 0; j < n_next; ++j) {
                    kept_x[j] = std::move(x[order[j]]);
                    kept_f[j] = fx[order[j]];
                }
                x = std::move(kept_x);
                fx = std::move(kept_f);
                archive_max = static_cast<std::size_t>(std::llround(s_.r_arc * static_cast<double>(n_next)));
                while (archive.size() > archive_max) {
                    const std::size_t drop = rng.below(archive.size());
                    archive[drop] = std::move(archive.back());
                    archive.pop_back();
                }
            }
            objective.end_iteration();
        }
    }

private:
    LshadeSettings s_;
};

} // namespace

void register_lshade(AlgorithmRegistry& registry) {
    registry.add(
        {"lshade",
         1,
         "L-SHADE: success-history adaptive DE with archive and linear population reduction (18D -> 4); "
         "N_G evaluations per iteration",
         "Tanabe and Fukunaga (2014), IEEE CEC 2014, pp. 1658-1665",
         {ParameterInfo::real("r_ninit", 18.0, 0.0, 1e4,
                              "initial population = round(r_ninit * D) (paper: 18)")
              .open_below(),
          ParameterInfo::integer("n_min", 4, 4, 1000000,
                                 "final population after reduction (paper: 4; current-to-pbest/1 needs 4)"),
          ParameterInfo::real("r_arc", 2.6, 0.0, 1e4, "archive size = round(r_arc * N) (paper: 2.6)"),
          ParameterInfo::real("p", 0.11, 0.0, 1.0,
                              "pbest drawn from the best max(2, round(p * N)) (paper: 0.11)")
              .open_below(),
          ParameterInfo::integer("H", 6, 1, 1000, "success-history memory slots (paper: 6)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             return std::make_unique<Lshade>(LshadeSettings{p.real("r_ninit"), p.integer("n_min"),
                                                            p.real("r_arc"), p.real("p"), p.integer("H")});
         }});
}

} // namespace mhb
