// jSO (Brest, Sepesy Maucec and Boskovic 2017, "Single objective real-parameter optimization:
// algorithm jSO", IEEE CEC 2017, pp. 1311-1318; second of the CEC 2017 competition): iL-SHADE, itself
// L-SHADE (algorithms/lshade.cpp) with a fixed high memory slot, stage-wise limits on CR and F and
// memory updates averaged with the old value, plus the weighted mutation current-to-pbest-w/1/bin.
//
// Checked against the authors' C++ code for CEC 2017 (Janez Brest, May 2017: lshade.cc, de.h,
// search_algorithm.cc and main.cc, kept in github.com/justinjk007/Pentagonal-tiling, archive/DE/,
// whose README.txt says it is jSO's code; its rawResults/ are the published runs). Where the paper's
// description and the code differ, the code is followed: it is what produced the published results
// (the paper's text itself was not at hand here; the description checked is the usual one of jSO,
// and every rule below was read in the code). Defaults (main.cc and lshade.cc):
//   N_init = round(25 sqrt(D) ln D) (natural log, nearest integer: 182 at D = 10, 466 at D = 30);
//   N_min = 4; H = 5 memory slots; archive size = N (rate 1.0, truncated to an integer as the code's
//   int conversion does); M_F starts at 0.3 and M_CR at 0.8 (the code's values; iL-SHADE had 0.5);
//   the last slot M_{F,H} = M_{CR,H} = 0.9 is fixed.
// Per trial vector, with nfes the evaluations spent when the generation began and MAX_NFE the budget:
//   r uniform in the H slots; CR ~ N(M_CR,r, 0.1) clipped to [0, 1], or 0 if M_CR,r < 0 (terminal);
//   then CR >= 0.7 while nfes < 0.25 MAX_NFE and CR >= 0.6 while nfes < 0.5 MAX_NFE (a terminal CR = 0
//   is raised too, as in the code). F ~ Cauchy(M_F,r, 0.1) redrawn while <= 0, cut at 1, and F <= 0.7
//   while nfes < 0.6 MAX_NFE. F_w = 0.7 F (nfes < 0.2 MAX_NFE), 0.8 F (< 0.4), else 1.2 F, and
//   v = x_i + F_w (x_pbest - x_i) + F (x_r1 - x_r2), binomial crossover with one forced coordinate.
//   pbest is uniform among the best p_num (ties in the ranking keep index order); while
//   nfes < 0.5 MAX_NFE it is redrawn until it is not x_i (iL-SHADE's rule, kept in the code).
//   r1 is uniform in the population without i; r2 uniform in population + archive, without i and r1
//   (not necessarily distinct from pbest), as in the code.
//   p goes linearly from p_max = 0.25 to p_max / 2 = 0.125: p = p_max (1 - 0.5 nfes / MAX_NFE), and
//   p_num = max(2, round(p N)). The code recomputes p and p_num only when the population shrinks
//   (every third generation at first, more rarely as N falls), and so does this one.
//   A coordinate that leaves the box is set halfway between the parent and the violated bound (the
//   code's modifySolutionWithParentMedium, JADE's rule), so the Objective's repair never acts.
// Selection: a trial at least as good as its parent replaces it; a strictly better one sends the
// parent to the archive (appended while there is room, else over a uniformly chosen member; the
// code keeps no archive below a size of 2, this one below 1: the same for the defaults, where the
// archive holds N >= 4) and records F, CR and the improvement. Memory update (slot k cycles over
// all H slots, including the fixed last one, whose stored value is never read: the code does the
// same):
//   M_F,k = (mean_WL(S_F) + M_F,k) / 2; M_CR,k = (mean_WL(S_CR) + M_CR,k) / 2, where mean_WL(S_CR)
//   is taken as -1 when every successful CR is 0. So a slot is not terminal for good as in L-SHADE
//   (M_CR = bottom stays bottom, algorithms/lshade.cpp): in the code -1 is averaged in like any value
//   and a later update can make the slot positive again. The code is followed.
// Linear population size reduction after each generation, from the evaluations actually spent:
//   N_next = max(N_min, round((N_min - N_init) / MAX_NFE nfes + N_init)); the worst are removed one by
//   one (the first of equal worst goes first), the survivors keep their order; the archive size
//   becomes floor(r_arc N_next), and an archive that is too large loses its last entries (the code
//   truncates, where algorithms/lshade.cpp drops at random).
//
// Budgets. With an evaluation budget MAX_NFE is that budget; every evaluation is charged through the
// Objective, so the last generation is cut exactly at the budget (the code evaluated the whole last
// generation and only stopped counting). With only an iteration budget G, MAX_NFE is derived as for
// L-SHADE so that LPSR reaches N_min near generation G: MAX_NFE = G (N_init - N_min) / ln(N_init / N_min)
// (G N_init when the two sizes are equal), and every nfes / MAX_NFE stage above uses it (capped at 1).
// Evaluations: N_init to initialise, then the current population size N_G per iteration.
//
// Compared with the authors' published final errors at the CEC 2017 protocol (D = 10, 51 runs,
// 100 000 evaluations, errors below 1e-8 as 0, F2 left out; scripts/compare-published.py, output in
// tests/data/published/cec2017/jso_D10_comparison.txt): two-sided rank-sum tests at alpha = 0.05 find
// 27 of 29 functions equal, none better and 2 worse, where 1.45 differ by chance alone: F7 (median
// 12.15 against 11.75, p = 0.0025) and F15 (0.43 against 0.18, p = 0.016). Neither survives a
// Bonferroni correction (0.05 / 29 = 0.0017), but they are not chance: 51 other runs (study seed 2,
// F7, F15, F20; jso_D10_seed2_F7_F15_F20_comparison.txt) give F7 worse again (p = 0.003) and F15
// (p = 0.006), F20 equal. Not explained yet. A line-by-line reading of lshade.cc found no step of the
// algorithm done otherwise here (the differences listed in this header are for ties, budgets cut
// short and random-number sources). Open leads: the CEC 2017 functions F7 (Lunacek bi-Rastrigin) and
// F15 (hybrid 5) as problems/cec/ computes them against the code the authors linked (the archive's
// copies of cec17_test_func.cc and search_algorithm.cc were edited after 2017 by the repository's
// owner: F7 calls sphere_func there and f* is 0, so they are not the code that made the runs). At
// D = 30 (jso_D30_comparison.txt) all 29 functions are equal. The published errors carry 6
// significant digits, so the script rounds mhbench's alike: unrounded, the runs that end at the same
// local optimum (F8, F20-F27) give spurious differences (9 functions differ unrounded at D = 10).
//
// Not reproduced: the code sets an f within 1e-8 of the known optimum to the optimum before
// selection (a CEC reporting rule, which turns near-ties into ties); mhbench's optimisers do not see
// f*. The code's rand()-based uniform draws (rand() / RAND_MAX, in [0, 1]) and Box-Muller normals are
// replaced by the run's Rng; the code's quicksort ranking by a stable one.
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

struct JsoSettings {
    double r_ninit = 25.0;
    long long n_min = 4;
    double r_arc = 1.0;
    double p_max = 0.25;
    long long memory = 5;
    double m_f = 0.3;
    double m_cr = 0.8;
};

// What each trial vector was made with (for the memory update of its success).
struct JsoTrialParameters {
    double cr;
    double f;
};

// round(r_ninit * sqrt(D) * ln D), and why jSO cannot run at D: a population the dimension makes
// smaller than n_min (D = 1 makes it 0), or one that does not fit in memory with its trials and
// archive.
std::size_t jso_initial_population(const JsoSettings& s, Eigen::Index dimension) {
    const auto dd = static_cast<double>(dimension);
    return static_cast<std::size_t>(std::llround(s.r_ninit * std::sqrt(dd) * std::log(dd)));
}

std::optional<std::string> jso_refusal(const JsoSettings& s, Eigen::Index dimension) {
    return shade_population_refusal("jso", "round(r_ninit * sqrt(D) * ln(D))",
                                    jso_initial_population(s, dimension), s.n_min, s.r_arc, dimension,
                                    "D = 1 needs another method");
}

// One jSO run: its population, memories and archive, and the steps of a generation.
class JsoRun {
public:
    JsoRun(const JsoSettings& settings, Objective& objective, Rng& rng)
        : s_(settings), objective_(objective), rng_(rng), h_(static_cast<std::size_t>(settings.memory)),
          m_cr_(h_, settings.m_cr), m_f_(h_, settings.m_f) {
        if (auto why = jso_refusal(s_, objective.dimension()))
            throw std::invalid_argument(*why);
        n_init_ = jso_initial_population(s_, objective.dimension());
        n_min_ = static_cast<std::size_t>(s_.n_min);
        max_nfe_ = shade::lpsr_max_evaluations(objective.budget(), static_cast<double>(n_init_),
                                               static_cast<double>(n_min_));
        archive_max_ = static_cast<std::size_t>(s_.r_arc * static_cast<double>(n_init_));
        p_num_ = std::max<std::size_t>(
            2, static_cast<std::size_t>(std::llround(s_.p_max * static_cast<double>(n_init_))));
        v_.resize(objective.dimension());
    }

    void run() {
        pop_ = random_population(objective_, rng_, n_init_);
        objective_.initialised();
        while (!objective_.exhausted()) {
            make_trials();
            // All trials come from the generation as it began: one batch, in index order. The
            // Objective stops it exactly at the evaluation budget (BudgetExhausted ends the run).
            objective_.evaluate_batch(trials_, f_trials_);
            select_survivors();
            update_memory();
            reduce_population();
            objective_.end_iteration();
        }
    }

private:
    // r uniform in the H slots (the last one fixed at 0.9), then CR and F with their stage limits.
    JsoTrialParameters draw_parameters(double stage) {
        const std::size_t r = rng_.below(h_);
        const double mu_cr = r == h_ - 1 ? 0.9 : m_cr_[r];
        const double mu_f = r == h_ - 1 ? 0.9 : m_f_[r];
        double cr = mu_cr < 0.0 ? 0.0 : std::clamp(mu_cr + 0.1 * rng_.normal(), 0.0, 1.0);
        if (stage < 0.25)
            cr = std::max(cr, 0.7);
        if (stage < 0.5)
            cr = std::max(cr, 0.6);
        double f = 0.0;
        do {
            f = mu_f + 0.1 * std::tan(std::numbers::pi * (rng_.uniform() - 0.5));
        } while (f <= 0.0);
        f = std::min(f, 1.0);
        if (stage < 0.6)
            f = std::min(f, 0.7);
        return {cr, f};
    }

    // current-to-pbest-w/1 into v_: pbest among the best p_num (not i in the first half), r1 from
    // the population without i, r2 from population + archive without i and r1.
    void mutate(std::size_t i, double f, double fw_factor) {
        const auto& x = pop_.x;
        const std::size_t n = x.size();
        std::size_t pbest = 0;
        do {
            pbest = order_[rng_.below(p_num_)];
        } while (stage_ < 0.5 && pbest == i);
        const auto [r1, r2] = shade::draw_r1_r2(rng_, i, n, archive_.size());
        const Eigen::VectorXd& x_r2 = r2 < n ? x[r2] : archive_[r2 - n];
        v_ = x[i] + (fw_factor * f) * (x[pbest] - x[i]) + f * (x[r1] - x_r2);
    }

    void make_trials() {
        const std::size_t n = pop_.x.size();
        stage_ = std::min(1.0, static_cast<double>(objective_.evaluations()) / max_nfe_);
        const double fw_factor = stage_ < 0.2 ? 0.7 : (stage_ < 0.4 ? 0.8 : 1.2);
        order_ = pop_.ranking();
        p_num_ = std::min(p_num_, n);
        trials_.assign(n, Eigen::VectorXd());
        f_trials_.assign(n, 0.0);
        used_.assign(n, {});
        for (std::size_t i = 0; i < n; ++i) {
            used_[i] = draw_parameters(stage_);
            mutate(i, used_[i].f, fw_factor);
            trials_[i] = shade::binomial_crossover(pop_.x[i], v_, used_[i].cr, objective_.bounds(), rng_);
        }
    }

    // A trial at least as good as its parent replaces it; a strictly better one archives the
    // parent and records its CR, F and improvement.
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
                archive_parent(x[i]);
                s_cr_.push_back(used_[i].cr);
                s_f_.push_back(used_[i].f);
                s_delta_.push_back(fx[i] - f_trials_[i]);
            }
            x[i] = std::move(trials_[i]);
            fx[i] = f_trials_[i];
        }
    }

    void archive_parent(const Eigen::VectorXd& parent) {
        if (archive_max_ == 0)
            return;
        if (archive_.size() < archive_max_)
            archive_.push_back(parent);
        else
            archive_[rng_.below(archive_max_)] = parent;
    }

    // Slot k becomes the average of its value and the weighted Lehmer mean of the successes.
    void update_memory() {
        if (s_f_.empty())
            return;
        const double mean_f = shade::weighted_lehmer_mean(s_f_, s_delta_);
        // Every successful CR was 0: the code's mean is -1 (see the header).
        const bool all_cr_zero = *std::max_element(s_cr_.begin(), s_cr_.end()) == 0.0;
        const double mean_cr = all_cr_zero ? -1.0 : shade::weighted_lehmer_mean(s_cr_, s_delta_);
        m_f_[k_memory_] = 0.5 * (mean_f + m_f_[k_memory_]);
        m_cr_[k_memory_] = 0.5 * (mean_cr + m_cr_[k_memory_]);
        k_memory_ = (k_memory_ + 1) % h_;
    }

    // Linear population size reduction from the evaluations spent; the archive and p follow.
    void reduce_population() {
        const auto nfes = static_cast<double>(objective_.evaluations());
        const std::size_t n_next = shade::lpsr_size(n_init_, n_min_, max_nfe_, nfes);
        if (n_next >= pop_.size())
            return;
        shade::remove_worst(pop_, n_next, shade::WorstTie::first);
        archive_max_ = static_cast<std::size_t>(s_.r_arc * static_cast<double>(n_next));
        if (archive_.size() > archive_max_)
            archive_.resize(archive_max_);
        const double p = s_.p_max * (1.0 - 0.5 * std::min(1.0, nfes / max_nfe_));
        p_num_ =
            std::max<std::size_t>(2, static_cast<std::size_t>(std::llround(p * static_cast<double>(n_next))));
    }

    const JsoSettings& s_;
    Objective& objective_;
    Rng& rng_;
    std::size_t h_, n_init_ = 0, n_min_ = 0, k_memory_ = 0, archive_max_ = 0, p_num_ = 0;
    double max_nfe_ = 0.0, stage_ = 0.0;
    std::vector<double> m_cr_, m_f_;
    Population pop_;
    std::vector<Eigen::VectorXd> archive_, trials_;
    std::vector<double> f_trials_, s_cr_, s_f_, s_delta_;
    std::vector<JsoTrialParameters> used_;
    std::vector<std::size_t> order_;
    Eigen::VectorXd v_;
};

class Jso final : public Optimizer {
public:
    explicit Jso(JsoSettings settings) : s_(settings) {}

    std::string name() const override { return "jso"; }

    void run(Objective& objective, Rng& rng) const override { JsoRun(s_, objective, rng).run(); }

    std::optional<std::string> refusal(Eigen::Index dimension) const override {
        return jso_refusal(s_, dimension);
    }

private:
    JsoSettings s_;
};

} // namespace

void register_jso(AlgorithmRegistry& registry) {
    registry.add(
        {"jso",
         1,
         "jSO: iL-SHADE with weighted current-to-pbest-w/1 mutation and stage-wise F/CR limits, linear "
         "population reduction (25 sqrt(D) ln D -> 4); N_G evaluations per iteration",
         "Brest, Sepesy Maucec and Boskovic (2017), IEEE CEC 2017, pp. 1311-1318",
         {ParameterInfo::real("r_ninit", 25.0, 0.0, 1e4,
                              "initial population = round(r_ninit * sqrt(D) * ln D) (paper and code: 25)")
              .open_below(),
          ParameterInfo::integer("n_min", 4, 4, 1000000,
                                 "final population after reduction (paper: 4; current-to-pbest/1 needs 4)"),
          ParameterInfo::real("r_arc", 1.0, 0.0, 1e4, "archive size = floor(r_arc * N) (paper: 1)"),
          ParameterInfo::real("p", 0.25, 0.0, 1.0,
                              "p_max: pbest from the best max(2, round(p N)), p falling linearly from p_max "
                              "to p_max/2 (paper: 0.25)")
              .open_below(),
          ParameterInfo::integer("H", 5, 1, 1000,
                                 "success-history memory slots, the last fixed at 0.9 (paper: 5)"),
          ParameterInfo::real("m_f", 0.3, 0.0, 1.0, "initial M_F (code: 0.3)").open_below(),
          ParameterInfo::real("m_cr", 0.8, 0.0, 1.0, "initial M_CR (code: 0.8)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             return std::make_unique<Jso>(JsoSettings{p.real("r_ninit"), p.integer("n_min"), p.real("r_arc"),
                                                      p.real("p"), p.integer("H"), p.real("m_f"),
                                                      p.real("m_cr")});
         }},
        {"jSO"});
}

} // namespace mhb
