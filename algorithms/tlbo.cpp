// TLBO, teaching-learning-based optimisation: R. V. Rao, V. J. Savsani, D. P. Vakharia (2011),
// "Teaching-learning-based optimization: A novel method for constrained mechanical design
// optimization problems", Computer-Aided Design 43(3):303-315. Written as eqs. 5-7 of Li, Wang,
// Ji (2017) restate it, read the way ARCHITECTURE.md section 9 asks.
//
// One iteration:
//   teacher phase, each learner i in index order: TF = round(1 + rand) in {1, 2};
//     X_new = X_i + r (X_teacher - TF Mean); greedy (keep if better);
//   learner phase (eq. 7, algorithms/classroom.hpp), each i in index order: a partner j != i;
//     X_new = X_i + r (X_i - X_j) if X_i is the better, else X_i + r (X_j - X_i); greedy.
// Evaluations: NP to initialise, then 2 NP per iteration, whichever r.
//
// Reading of "in place". Learners are replaced one after another, so learner i sees the class
// as learners 0..i-1 left it. Mean and the teacher are therefore those of the class at the
// moment learner i is taught, not a snapshot from the start of the phase: the teacher is the
// current best learner (lowest index among equals), and Mean is kept as a running sum updated
// at every replacement and recomputed exactly at the start of every teacher phase.
//
// The learning factor r, parameter `r`:
//   coordinate (default)  one uniform draw per coordinate: the step is diag(r_1..r_D) times the
//                         direction. ARCHITECTURE.md section 9; every result before `r` existed.
//   learner               one uniform draw per learner and step, used for every coordinate.
// What the papers write. Li, Wang, Ji (2017) put a scalar "rand" in eq. 6 and say of eq. 7
// "r_i = rand(0,1) is the learning factor of the i-th learner": one per learner, so `learner`
// is the paper's reading. Rao, Savsani, Vakharia (2011) write Difference_Mean_i =
// r_i (M_new - T_F M_i) and X_new,i = X_old,i + r_i (X_i - X_j) with r_i "a random number in the
// range [0, 1]": a scalar by its notation (in the teacher phase i counts iterations there), but
// the text does not say whether a fresh number is drawn per variable. That is from our reading of
// the paper and not re-checked for this file; treat it as uncertain. Common codings (Yarpiz's
// MATLAB TLBO, for one) draw rand(1, D), one per coordinate, which is our default.
// Why it matters. With one r per learner the step is a multiple of a vector the class defines
// (X_teacher - TF Mean, or X_i - X_j): rotate the problem and every trial point rotates with it,
// so TLBO is rotation-invariant (apart from the axis-aligned initial box and the clamping).
// With one r per coordinate each component of the step is scaled independently, which spreads
// the trial points over the axis-aligned box spanned by the step: the search leans towards the
// axes, which favours separable functions (each coordinate can improve on its own) and makes
// results change when the same function is rotated.
//
// Random draws, in order: initial positions (learner by learner, coordinate by coordinate);
// per teacher step TF, then r_1..r_D (coordinate) or one r (learner); per learner step j, then
// r_1..r_D or one r.
//
// Default: NP = 50, the paper's population (section 4.1). Bounds are repaired by clamping
// (the Objective's default, as in the paper).
#include <cmath>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/classroom.hpp"
#include "algorithms/population_limits.hpp"

namespace mhb {
namespace {

class Tlbo final : public Optimizer {
public:
    Tlbo(Eigen::Index np, detail::LearningFactor r_mode) : np_(np), r_mode_(r_mode) {}

    std::string name() const override { return "tlbo"; }

    // The class, its new candidates and the batch being evaluated.
    std::optional<std::string> refusal(Eigen::Index dimension) const override {
        return population_memory_refusal("tlbo", 3.0 * static_cast<double>(np_), dimension, "np");
    }

    void run(Objective& objective, Rng& rng) const override {
        detail::Classroom c(objective, rng, np_);
        objective.initialised();
        Eigen::VectorXd trial(objective.dimension());
        while (!objective.exhausted()) {
            c.resum();
            teacher_phase(c, objective, rng, trial);
            detail::learner_phase(c, objective, rng, trial, r_mode_);
            objective.end_iteration();
        }
    }

private:
    // Eq. 6 of Li, Wang, Ji (2017): X_new = X_i + r (X_teacher - TF Mean).
    void teacher_phase(detail::Classroom& c, Objective& objective, Rng& rng, Eigen::VectorXd& trial) const {
        for (Eigen::Index i = 0; i < c.size(); ++i) {
            const double tf = std::round(1.0 + rng.uniform());
            const auto xi = c.learner(i);
            const auto teacher = c.learner(c.teacher());
            if (r_mode_ == detail::LearningFactor::learner) {
                const double r = rng.uniform();
                for (Eigen::Index k = 0; k < trial.size(); ++k)
                    trial[k] = xi[k] + r * (teacher[k] - tf * c.mean(k));
            } else {
                for (Eigen::Index k = 0; k < trial.size(); ++k)
                    trial[k] = xi[k] + rng.uniform() * (teacher[k] - tf * c.mean(k));
            }
            const double f = objective.evaluate(trial);
            if (f < c.fitness(i))
                c.replace(i, trial, f);
        }
    }

    Eigen::Index np_;
    detail::LearningFactor r_mode_;
};

} // namespace

void register_tlbo(AlgorithmRegistry& registry) {
    registry.add(
        {"tlbo",
         1,
         "teaching-learning-based optimisation: teacher phase then learner phase, greedy, "
         "in place; 2 NP evaluations per iteration",
         "Rao, Savsani, Vakharia (2011), Computer-Aided Design 43(3):303-315",
         {ParameterInfo::integer("np", 50, 2, 100000,
                                 "population (learners); 50 as in Li, Wang, Ji (2017), section 4.1"),
          ParameterInfo::choice("r", "coordinate", {"coordinate", "learner"},
                                "learning factor: one draw per coordinate (default; rotation-dependent, "
                                "favours separable functions) or one per learner and step for every "
                                "coordinate (Li, Wang, Ji's 'i-th learner's learning factor'; "
                                "rotation-invariant)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             return std::make_unique<Tlbo>(static_cast<Eigen::Index>(p.integer("np")),
                                           detail::learning_factor_from(p.text("r")));
         }},
        {"TLBO"});
}

} // namespace mhb
