// TLBO, teaching-learning-based optimisation: R. V. Rao, V. J. Savsani, D. P. Vakharia (2011),
// "Teaching-learning-based optimization: A novel method for constrained mechanical design
// optimization problems", Computer-Aided Design 43(3):303-315. Written as eqs. 5-7 of Li, Wang,
// Ji (2017) restate it, read the way DESIGN.md section 4 asks.
//
// One iteration:
//   teacher phase, each learner i in index order: TF = round(1 + rand) in {1, 2};
//     X_new = X_i + r (X_teacher - TF Mean), r uniform per coordinate; greedy (keep if better);
//   learner phase (eq. 7, algorithms/classroom.hpp), each i in index order: a partner j != i;
//     a step towards the better of the two, away from the worse; greedy.
// Evaluations: NP to initialise, then 2 NP per iteration.
//
// Reading of "in place". Learners are replaced one after another, so learner i sees the class
// as learners 0..i-1 left it. Mean and the teacher are therefore those of the class at the
// moment learner i is taught, not a snapshot from the start of the phase: the teacher is the
// current best learner (lowest index among equals), and Mean is kept as a running sum updated
// at every replacement and recomputed exactly at the start of every teacher phase.
// Random draws, in order: initial positions (learner by learner, coordinate by coordinate);
// per teacher step TF, then r_1..r_D; per learner step j, then r_1..r_D.
//
// Default: NP = 50, the paper's population (section 4.1). Bounds are repaired by clamping
// (the Objective's default, as in the paper).
#include <cmath>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/classroom.hpp"

namespace mhb {
namespace {

class Tlbo final : public Optimizer {
public:
    explicit Tlbo(Eigen::Index np) : np_(np) {}

    std::string name() const override { return "tlbo"; }

    void run(Objective& objective, Rng& rng) const override {
        detail::Classroom c(objective, rng, np_);
        objective.initialised();
        Eigen::VectorXd trial(objective.dimension());
        while (!objective.exhausted()) {
            c.resum();
            teacher_phase(c, objective, rng, trial);
            detail::learner_phase(c, objective, rng, trial);
            objective.end_iteration();
        }
    }

private:
    // Eq. 6 of Li, Wang, Ji (2017): X_new = X_i + r (X_teacher - TF Mean).
    static void teacher_phase(detail::Classroom& c, Objective& objective, Rng& rng, Eigen::VectorXd& trial) {
        for (Eigen::Index i = 0; i < c.size(); ++i) {
            const double tf = std::round(1.0 + rng.uniform());
            const auto xi = c.learner(i);
            const auto teacher = c.learner(c.teacher());
            for (Eigen::Index k = 0; k < trial.size(); ++k)
                trial[k] = xi[k] + rng.uniform() * (teacher[k] - tf * c.mean(k));
            const double f = objective.evaluate(trial);
            if (f < c.fitness(i))
                c.replace(i, trial, f);
        }
    }

    Eigen::Index np_;
};

} // namespace

void register_tlbo(AlgorithmRegistry& registry) {
    registry.add(
        {"tlbo",
         "teaching-learning-based optimisation: teacher phase then learner phase, greedy, "
         "in place; 2 NP evaluations per iteration",
         "Rao, Savsani, Vakharia (2011), Computer-Aided Design 43(3):303-315",
         {ParameterInfo::integer("np", 50, 2, 100000,
                                 "population (learners); 50 as in Li, Wang, Ji (2017), section 4.1")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             return std::make_unique<Tlbo>(static_cast<Eigen::Index>(p.integer("np")));
         }});
}

} // namespace mhb
