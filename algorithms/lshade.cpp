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
#include "algorithms/population_limits.hpp"
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

// round(r_ninit * D), and why L-SHADE cannot run at D: a population the dimension makes smaller
// than n_min, or one whose population, trials and archive do not fit in memory.
std::size_t lshade_initial_population(const LshadeSettings& s, Eigen::Index dimension) {
    return static_cast<std::size_t>(std::llround(s.r_ninit * static_cast<double>(dimension)));
}

std::optional<std::string> lshade_refusal(const LshadeSettings& s, Eigen::Index dimension) {
    return shade_population_refusal("lshade", "round(r_ninit * D)", lshade_initial_population(s, dimension),
                                    s.n_min, s.r_arc, dimension, "the population is too small");
}

// One L-SHADE run: its population, memories and archive, and the steps of a generation.
class LshadeRun {
public:
    LshadeRun(const LshadeSettings& settings, Objective& objective, Rng& rng)
        : s_(settings), objective_(objective), rng_(rng), h_(static_cast<std::size_t>(settings.memory)),
          m_cr_(h_, 0.5), m_f_(h_, 0.5), cr_terminal_(h_, false) {
        if (auto why = lshade_refusal(s_, objective.dimension()))
            throw std::invalid_argument(*why);
        n_init_ = lshade_initial_population(s_, objective.dimension());
        n_min_ = static_cast<std::size_t>(s_.n_min);
        max_nfe_ = shade::lpsr_max_evaluations(objective.budget(), static_cast<double>(n_init_),
                                               static_cast<double>(n_min_));
        archive_max_ = static_cast<std::size_t>(std::llround(s_.r_arc * static_cast<double>(n_init_)));
        v_.resize(objective.dimension());
    }

    void run() {
        pop_ = random_population(objective_, rng_, n_init_);
        objective_.initialised();
        while (!objective_.exhausted()) {
            make_trials();
            // Every trial is built from the generation as it began, so they are evaluated as one
            // batch (in parallel for an expensive problem), in index order, before any selection.
            objective_.evaluate_batch(trials_, f_trials_);
            select_survivors();
            update_memory();
            reduce_population();
            objective_.end_iteration();
        }
    }

private:
    // r uniform in the H slots; CR ~ N(M_CR, 0.1) clipped (0 once the slot is terminal), F ~
    // Cauchy(M_F, 0.1) redrawn while <= 0 and cut at 1; then current-to-pbest/1 into v_.
    void make_trial(std::size_t i, std::size_t n_pbest) {
        const auto& x = pop_.x;
        const std::size_t n = x.size();
        const std::size_t r = rng_.below(h_);
        cr_used_[i] = cr_terminal_[r] ? 0.0 : std::clamp(m_cr_[r] + 0.1 * rng_.normal(), 0.0, 1.0);
        double f = 0.0;
        do {
            f = m_f_[r] + 0.1 * std::tan(std::numbers::pi * (rng_.uniform() - 0.5));
        } while (f <= 0.0);
        f_used_[i] = std::min(f, 1.0);

        const Eigen::VectorXd& pbest = x[order_[rng_.below(n_pbest)]];
        const auto [r1, r2] = shade::draw_r1_r2(rng_, i, n, archive_.size());
        const Eigen::VectorXd& x_r2 = r2 < n ? x[r2] : archive_[r2 - n];

        const double fi = f_used_[i];
        v_ = x[i] + fi * (pbest - x[i]) + fi * (x[r1] - x_r2);
        trials_[i] = shade::binomial_crossover(x[i], v_, cr_used_[i], objective_.bounds(), rng_);
    }

    void make_trials() {
        const std::size_t n = pop_.x.size();
        order_ = pop_.ranking();
        const std::size_t n_pbest = std::max<std::size_t>(
            2, static_cast<std::size_t>(std::llround(s_.p_best * static_cast<double>(n))));
        trials_.assign(n, Eigen::VectorXd());
        f_trials_.assign(n, 0.0);
        cr_used_.assign(n, 0.0);
        f_used_.assign(n, 0.0);
        for (std::size_t i = 0; i < n; ++i)
            make_trial(i, n_pbest);
    }

    // Selection, archive and the successful parameters.
    void select_survivors() {
        auto& x = pop_.x;
        auto& fx = pop_.f;
        s_cr_.clear();
        s_f_.clear();
        s_delta_.clear();
        for (std::size_t i = 0; i < x.size(); ++i) {
            if (f_trials_[i] > fx[i])
                continue;
            if (f_trials_[i] < fx[i]) {
                if (archive_max_ > 0) {
                    if (archive_.size() < archive_max_)
                        archive_.push_back(x[i]);
                    else
                        archive_[rng_.below(archive_.size())] = x[i];
                }
                s_cr_.push_back(cr_used_[i]);
                s_f_.push_back(f_used_[i]);
                s_delta_.push_back(fx[i] - f_trials_[i]);
            }
            x[i] = std::move(trials_[i]);
            fx[i] = f_trials_[i];
        }
    }

    void update_memory() {
        if (s_f_.empty())
            return;
        const bool all_cr_zero = *std::max_element(s_cr_.begin(), s_cr_.end()) == 0.0;
        if (cr_terminal_[k_memory_] || all_cr_zero)
            cr_terminal_[k_memory_] = true;
        else
            m_cr_[k_memory_] = shade::weighted_lehmer_mean(s_cr_, s_delta_);
        m_f_[k_memory_] = shade::weighted_lehmer_mean(s_f_, s_delta_);
        k_memory_ = (k_memory_ + 1) % h_;
    }

    // Linear population size reduction: drop the worst, shrink the archive at random.
    void reduce_population() {
        auto& x = pop_.x;
        auto& fx = pop_.f;
        const std::size_t n_next =
            shade::lpsr_size(n_init_, n_min_, max_nfe_, static_cast<double>(objective_.evaluations()));
        if (n_next >= x.size())
            return;
        order_ = pop_.ranking();
        std::vector<Eigen::VectorXd> kept_x(n_next);
        std::vector<double> kept_f(n_next);
        std::sort(order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(n_next)); // keep index order
        for (std::size_t j = 0; j < n_next; ++j) {
            kept_x[j] = std::move(x[order_[j]]);
            kept_f[j] = fx[order_[j]];
        }
        x = std::move(kept_x);
        fx = std::move(kept_f);
        archive_max_ = static_cast<std::size_t>(std::llround(s_.r_arc * static_cast<double>(n_next)));
        while (archive_.size() > archive_max_) {
            const std::size_t drop = rng_.below(archive_.size());
            archive_[drop] = std::move(archive_.back());
            archive_.pop_back();
        }
    }

    const LshadeSettings& s_;
    Objective& objective_;
    Rng& rng_;
    std::size_t h_, n_init_ = 0, n_min_ = 0, k_memory_ = 0, archive_max_ = 0;
    double max_nfe_ = 0.0;
    std::vector<double> m_cr_, m_f_;
    std::vector<bool> cr_terminal_;
    Population pop_;
    std::vector<Eigen::VectorXd> archive_, trials_;
    std::vector<double> f_trials_, cr_used_, f_used_, s_cr_, s_f_, s_delta_;
    std::vector<std::size_t> order_;
    Eigen::VectorXd v_;
};

class Lshade final : public Optimizer {
public:
    explicit Lshade(LshadeSettings settings) : s_(settings) {}

    std::string name() const override { return "lshade"; }

    void run(Objective& objective, Rng& rng) const override { LshadeRun(s_, objective, rng).run(); }

    std::optional<std::string> refusal(Eigen::Index dimension) const override {
        return lshade_refusal(s_, dimension);
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
         }},
        {"L-SHADE"});
}

} // namespace mhb
