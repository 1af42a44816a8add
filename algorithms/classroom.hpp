// The class of learners that TLBO (algorithms/tlbo.cpp) and ITLBO (algorithms/itlbo.cpp) both
// teach: positions, fitness, the running sum behind "Mean" and the index of the teacher, kept
// consistent while learners are replaced in place, one at a time. Plus the one step the two
// algorithms share by definition: the learner phase of eq. 7 (TLBO's, which ITLBO keeps when
// its subject-stepwise learning is off).
//
// Also the choice both (and PSO, in its own terms) offer for the learning factor r: one uniform
// draw per coordinate (`r=coordinate`, the default) or one per learner and step, used for every
// coordinate (`r=learner`); tlbo.cpp's header says which the papers use and what each favours.
//
// Only bookkeeping and that shared phase live here. Each algorithm writes its own teacher phase,
// its own main loop and its own extras, so that the test "ITLBO with its three switches off is
// TLBO, bit for bit" compares two separate codings and can fail.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "algorithms/sampling.hpp"
#include "problems/core/rng.hpp"
#include "problems/objective.hpp"

namespace mhb::detail {

// How the learning factor r of eqs. 6-9 is drawn: per coordinate, or once per learner and step.
enum class LearningFactor { coordinate, learner };

// The registry's spelling, `r=coordinate|learner`.
inline LearningFactor learning_factor_from(const std::string& text) {
    return text == "learner" ? LearningFactor::learner : LearningFactor::coordinate;
}

class Classroom {
public:
    // Draws `np` learners uniformly in the box (eq. 5: learner by learner, coordinate by
    // coordinate), then evaluates them in index order as one batch: np evaluations. No draw
    // depends on an f, so this is drawing and evaluating one learner at a time, bit for bit.
    Classroom(Objective& objective, Rng& rng, Eigen::Index np)
        : x_(objective.dimension(), np), f_(np), sum_(objective.dimension()),
          inverse_size_(1.0 / static_cast<double>(np)) {
        std::vector<Eigen::VectorXd> learners(static_cast<std::size_t>(np));
        for (auto& learner : learners)
            learner = uniform_point(objective.bounds(), rng);
        objective.evaluate_batch(learners, std::span<double>(f_.data(), learners.size()));
        for (Eigen::Index i = 0; i < np; ++i)
            x_.col(i) = learners[static_cast<std::size_t>(i)];
        resum();
        find_teacher();
    }

    [[nodiscard]] Eigen::Index size() const { return x_.cols(); }
    [[nodiscard]] Eigen::Index dimension() const { return x_.rows(); }
    [[nodiscard]] auto learner(Eigen::Index i) const { return x_.col(i); }
    [[nodiscard]] double fitness(Eigen::Index i) const { return f_[i]; }
    [[nodiscard]] const Eigen::MatrixXd& positions() const { return x_; }

    // The teacher is the best learner of the class as it is now; among equal fitness, the
    // lowest index. Kept up to date by replace().
    [[nodiscard]] Eigen::Index teacher() const { return teacher_; }

    // "Mean" of eqs. 6 and 8, coordinate k, of the class as it is now. It comes from a running
    // sum updated at every replacement (O(D) instead of O(NP D) per learner); resum() makes it
    // exact again, and both algorithms call it at the start of every teacher phase, so rounding
    // drift never outlives one phase. (Multiplying by 1/NP rather than dividing by NP: a division
    // per coordinate and learner was the largest cost of TLBO's own code.)
    [[nodiscard]] double mean(Eigen::Index k) const { return sum_[k] * inverse_size_; }

    void resum() { sum_ = x_.rowwise().sum(); }

    // Learner i becomes `x`, of fitness f: a greedy acceptance, or an unconditional replacement
    // (ITLBO's opposition-based mutation), which may make the teacher worse.
    void replace(Eigen::Index i, const Eigen::VectorXd& x, double f) {
        sum_ += x - x_.col(i);
        x_.col(i) = x;
        const bool was_teacher = i == teacher_;
        const double old_f = f_[i];
        f_[i] = f;
        if (f < f_[teacher_] || (f == f_[teacher_] && i < teacher_))
            teacher_ = i;
        else if (was_teacher && f > old_f)
            find_teacher();
    }

private:
    void find_teacher() {
        Eigen::Index best = 0;
        for (Eigen::Index i = 1; i < f_.size(); ++i)
            if (f_[i] < f_[best])
                best = i;
        teacher_ = best;
    }

    Eigen::MatrixXd x_;   // D x NP, one learner per column (contiguous)
    Eigen::VectorXd f_;   // fitness of each learner
    Eigen::VectorXd sum_; // running sum of the columns of x_
    double inverse_size_; // 1 / NP
    Eigen::Index teacher_ = 0;
};

// The learner phase of TLBO (Rao et al. 2011; eq. 7 of Li, Wang, Ji 2017). For each learner i in
// index order: a partner j != i, read as it is at that moment; X_new = X_i + r (X_i - X_j) if
// f(X_i) < f(X_j), else X_i + r (X_j - X_i); greedy. r is uniform per coordinate (`coordinate`)
// or one uniform for the whole step (`learner`, eq. 7's "r_i, the i-th learner's learning
// factor"). Draws per learner: j, then r_1..r_D or the one r. NP evaluations. `trial` is a
// buffer of size D.
inline void learner_phase(Classroom& c, Objective& objective, Rng& rng, Eigen::VectorXd& trial,
                          LearningFactor r_mode) {
    const auto np = static_cast<std::uint64_t>(c.size());
    for (Eigen::Index i = 0; i < c.size(); ++i) {
        const auto j = static_cast<Eigen::Index>(rng.below_except(np, static_cast<std::uint64_t>(i)));
        const auto xi = c.learner(i);
        const auto xj = c.learner(j);
        const bool away = c.fitness(i) < c.fitness(j); // from the worse partner, or towards the better
        if (r_mode == LearningFactor::learner) {
            const double r = rng.uniform();
            for (Eigen::Index k = 0; k < trial.size(); ++k)
                trial[k] = xi[k] + r * (away ? xi[k] - xj[k] : xj[k] - xi[k]);
        } else if (away) {
            for (Eigen::Index k = 0; k < trial.size(); ++k)
                trial[k] = xi[k] + rng.uniform() * (xi[k] - xj[k]);
        } else {
            for (Eigen::Index k = 0; k < trial.size(); ++k)
                trial[k] = xi[k] + rng.uniform() * (xj[k] - xi[k]);
        }
        const double f = objective.evaluate(trial);
        if (f < c.fitness(i))
            c.replace(i, trial, f);
    }
}

} // namespace mhb::detail
