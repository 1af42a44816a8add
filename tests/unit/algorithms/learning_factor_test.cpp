// The learning factor `r` of TLBO, ITLBO and PSO (tlbo.cpp, itlbo.cpp, pso.cpp): the default,
// `coordinate`, is the behaviour every earlier result was made with, value for value; `learner`
// draws one r per learner and step, so a step is a multiple of one vector the class defines
// (checked on the points actually evaluated, recorded by RecordingProblem); and `learner` is a
// different run from `coordinate`.
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "tests/unit/algorithms/paper_algorithms_support.hpp"

namespace mhb::test {
namespace {

struct Reference {
    const char* algorithm;
    const char* problem;
    std::uint64_t seed;
    double best_f;
    double first; // best x, first coordinate
    double last;  // best x, last coordinate
};

// Captured with the code as it was BEFORE `r` existed (commit 1884dfa, 20 iterations from
// Rng(seed), printed with %a): the pre-change values, which the default `r=coordinate` must keep
// exactly. ITLBO with obl on is not here: its mutation stream changed (a jumped copy of the run's
// stream instead of a seed peeked from it), so its runs differ from the pre-change ones; with obl
// off its draws are untouched and so are its values.
const Reference pre_change[] = {
    {"tlbo", "sphere", 1ULL, 0x1.2e845f1ef6027p-1, -0x1.bc33cbf7f9e8bp-4, 0x1.2fa9d8add2ae6p-3},
    {"tlbo", "sphere", 99ULL, 0x1.bf7e5785d4792p-2, 0x1.bc00fab2e3068p-4, 0x1.31ded36c787d2p-2},
    {"tlbo", "rosenbrock", 1ULL, 0x1.a594b3dc9c559p+0, 0x1.7f39f5e6a1b3ap-1, 0x1.449f79bc8c50ap-6},
    {"tlbo", "rosenbrock", 99ULL, 0x1.2e0b5060caaf2p+1, 0x1.3ed572870b2e4p-1, -0x1.3725128506efep-5},
    {"tlbo:np=7", "sphere", 1ULL, 0x1.aa7defb8652e3p-4, -0x1.7273c43115359p-4, -0x1.396fda0cc695p-5},
    {"tlbo:np=7", "sphere", 99ULL, 0x1.382980c6e0f32p-1, -0x1.b7487a61f075cp-4, 0x1.ed7e80d198d4p-7},
    {"tlbo:np=7", "rosenbrock", 1ULL, 0x1.b62ba2d0e6baep+1, 0x1.24610c2d39152p-2, -0x1.4ab6956108eb3p-6},
    {"tlbo:np=7", "rosenbrock", 99ULL, 0x1.2bc411b130837p+2, -0x1.4141f86b33bb8p-1, 0x1.4c32f12a5c724p-9},
    {"pso", "sphere", 1ULL, 0x1.ac4fc44ba7f4ep+7, 0x1.5e41d3622642p-2, 0x1.f810d0fe0d678p+1},
    {"pso", "sphere", 99ULL, 0x1.42e0ee4e4826ep+9, 0x1.1c23fde80153ep+3, -0x1.172f4d5854c14p+2},
    {"pso", "rosenbrock", 1ULL, 0x1.8e924b9529e01p+3, 0x1.770a9053fff03p-4, -0x1.e32676f2b4468p-7},
    {"pso", "rosenbrock", 99ULL, 0x1.bf800bffff9bp+1, 0x1.6ad98dd3cde87p-1, -0x1.227e9e8ff7d2cp-4},
    {"pso:np=9,vmax=0.2", "sphere", 1ULL, 0x1.15bd1409b7b13p+8, -0x1.1638accf29316p+3, 0x1.d340592001574p+2},
    {"pso:np=9,vmax=0.2", "sphere", 99ULL, 0x1.cec70b3ca6afdp+7, 0x1.e858b3400bd4p+0, -0x1.3d99855090fbdp+0},
    {"pso:np=9,vmax=0.2", "rosenbrock", 1ULL, 0x1.394c40cdf5185p+6, 0x1.5fc458197ede9p-2,
     0x1.c967bc2a6c67ap+0},
    {"pso:np=9,vmax=0.2", "rosenbrock", 99ULL, 0x1.d5577a92a3e85p+2, -0x1.7ae31215a0209p-3,
     0x1.09b6da8fbfa92p-4},
    {"itlbo:obl=off", "sphere", 1ULL, 0x1.beaa53ce26b1bp-24, -0x1.a5f8d5c40680ap-15, -0x1.435ac2299c3d3p-16},
    {"itlbo:obl=off", "sphere", 99ULL, 0x1.2e17270a68a4dp-25, -0x1.15185ce5eca2p-18, 0x1.23fcfe34eb98p-18},
    {"itlbo:obl=off", "rosenbrock", 1ULL, 0x1.2be1603b28828p+0, 0x1.a60467aecb35cp-1, 0x1.2fa02b50a98d5p-5},
    {"itlbo:obl=off", "rosenbrock", 99ULL, 0x1.c840f7d68ef42p-1, 0x1.b7023f2684ac2p-1, 0x1.d8287690be9fap-5},
    {"itlbo:tutorial=off,obl=off", "sphere", 1ULL, 0x1.04947ec427771p-6, -0x1.0b5177f20e984p-5,
     0x1.b3dabe2170054p-5},
    {"itlbo:tutorial=off,obl=off", "sphere", 99ULL, 0x1.2a932a07f0857p-7, -0x1.2d6550171bdfp-5,
     0x1.8cecdef91aep-8},
    {"itlbo:tutorial=off,obl=off", "rosenbrock", 1ULL, 0x1.045c3023ed8aep+0, 0x1.0d060f0ce6e72p+0,
     0x1.7a1ff06a3fa95p+0},
    {"itlbo:tutorial=off,obl=off", "rosenbrock", 99ULL, 0x1.f13dddf8c26a5p-2, 0x1.e3d84ebabefa5p-1,
     0x1.d6fa216345747p-2},
};

TEST(LearningFactor, CoordinateModeKeepsThePreChangeValues) {
    const auto sphere10 = sphere(10);
    const Rosenbrock rosenbrock5(5);
    for (const Reference& want : pre_change) {
        const Problem& problem = std::string(want.problem) == "sphere"
                                     ? static_cast<const Problem&>(*sphere10)
                                     : static_cast<const Problem&>(rosenbrock5);
        const Outcome o = run(want.algorithm, problem, want.seed, iterations(20));
        const std::string what =
            std::string(want.algorithm) + " on " + want.problem + ", seed " + std::to_string(want.seed);
        EXPECT_EQ(o.best_f, want.best_f) << what;
        EXPECT_EQ(o.best_x[0], want.first) << what;
        EXPECT_EQ(o.best_x[o.best_x.size() - 1], want.last) << what;
        // Saying `r=coordinate` is the same as saying nothing.
        const std::string spec = want.algorithm;
        const std::string explicit_spec =
            spec + (spec.find(':') == std::string::npos ? ":" : ",") + "r=coordinate";
        EXPECT_TRUE(identical(o, run(explicit_spec, problem, want.seed, iterations(20)))) << explicit_spec;
    }
}

// `r=learner` changes the draws, so it is another run, for every algorithm that offers it.
TEST(LearningFactor, LearnerModeIsAnotherRun) {
    const Rosenbrock problem(5);
    for (const std::string algorithm : {"tlbo", "itlbo", "pso"}) {
        const Outcome coordinate = run(algorithm, problem, 3, iterations(15));
        const Outcome learner = run(algorithm + ":r=learner", problem, 3, iterations(15));
        EXPECT_FALSE(identical(coordinate, learner)) << algorithm;
        EXPECT_TRUE(identical(learner, run(algorithm + ":r=learner", problem, 3, iterations(15))))
            << algorithm;
    }
}

// |d - t v| small against the sizes involved, where t = d.v / v.v: d is t times v, up to the last
// bits of a Mean kept as a running sum.
bool along(const Eigen::VectorXd& d, const Eigen::VectorXd& v, double scale, double& t) {
    const double vv = v.squaredNorm();
    if (vv == 0.0)
        return false;
    t = d.dot(v) / vv;
    return (d - t * v).norm() <= 1e-9 * (scale + v.norm());
}

bool clamped(const Eigen::VectorXd& x, const Box& box) {
    return (x.array() == box.lower.array()).any() || (x.array() == box.upper.array()).any();
}

// How many of TLBO's steps, recorded in order, were a multiple of the direction their rule
// prescribes: teacher steps X_new - X_i = r (X_teacher - TF Mean), TF in {1, 2}, r in [0, 1),
// with the teacher and Mean of the class as it is when learner i is taught; learner steps
// X_new - X_i = r (X_i - X_j) or r (X_j - X_i) for some partner j. Steps that hit the box are
// skipped (clamping changes their direction).
struct Tally {
    int checked = 0;
    int teacher_along = 0;
    int learner_along = 0;
};

Tally tally_tlbo_steps(const RecordingProblem& rec, std::size_t np, int iterations_run) {
    std::vector<Eigen::VectorXd> x;
    std::vector<double> f;
    for (std::size_t i = 0; i < np; ++i) {
        x.push_back(rec.points.at(i));
        f.push_back(rec.f(i));
    }
    const Box& box = rec.bounds();
    const auto accept = [&](std::size_t i, std::size_t n) {
        if (rec.f(n) < f[i]) {
            x[i] = rec.points[n];
            f[i] = rec.f(n);
        }
    };
    Tally tally;
    std::size_t n = np;
    for (int it = 0; it < iterations_run; ++it) {
        for (std::size_t i = 0; i < np; ++i, ++n) { // teacher phase
            std::size_t teacher = 0;
            Eigen::VectorXd mean = Eigen::VectorXd::Zero(x[0].size());
            for (std::size_t m = 0; m < np; ++m) {
                mean += x[m];
                if (f[m] < f[teacher])
                    teacher = m;
            }
            mean /= static_cast<double>(np);
            const Eigen::VectorXd& q = rec.points.at(n);
            if (!clamped(q, box)) {
                ++tally.checked;
                const double scale = x[i].norm();
                for (const double tf : {1.0, 2.0}) {
                    double t = 0.0;
                    if (along(q - x[i], x[teacher] - tf * mean, scale, t) && t >= 0.0 && t < 1.0) {
                        ++tally.teacher_along;
                        break;
                    }
                }
            }
            accept(i, n);
        }
        for (std::size_t i = 0; i < np; ++i, ++n) { // learner phase
            const Eigen::VectorXd& q = rec.points.at(n);
            if (!clamped(q, box)) {
                for (std::size_t j = 0; j < np; ++j) {
                    double t = 0.0;
                    const double sign = f[i] < f[j] ? 1.0 : -1.0; // away from a worse j, towards a better
                    if (j != i && along(q - x[i], sign * (x[i] - x[j]), x[i].norm(), t) && t >= 0.0 &&
                        t < 1.0) {
                        ++tally.learner_along;
                        break;
                    }
                }
            }
            accept(i, n);
        }
    }
    return tally;
}

// Learner mode (eq. 6 with eq. 7's "r_i, the i-th learner's learning factor"): every teacher step
// of TLBO moves X_i exactly along X_teacher - TF Mean, every learner step along X_i - X_j. In
// coordinate mode almost none does, which shows the check can tell the two apart.
TEST(LearningFactor, TlboLearnerModeStepsAlongTheClassDirection) {
    const auto inner = sphere(5);
    const std::size_t np = 8;
    const int its = 6;
    for (const std::uint64_t seed : {5ULL, 6ULL, 7ULL}) {
        const RecordingProblem learner(*inner);
        run("tlbo:np=8,r=learner", learner, seed, iterations(its));
        ASSERT_EQ(learner.points.size(), np + static_cast<std::size_t>(its) * 2 * np);
        const Tally l = tally_tlbo_steps(learner, np, its);
        EXPECT_GT(l.checked, 30) << "seed " << seed << ": too many steps clamped to check";
        EXPECT_EQ(l.teacher_along, l.checked) << "seed " << seed;

        const RecordingProblem coordinate(*inner);
        run("tlbo:np=8", coordinate, seed, iterations(its));
        const Tally c = tally_tlbo_steps(coordinate, np, its);
        EXPECT_LT(c.teacher_along, c.checked / 10) << "seed " << seed;
        EXPECT_LT(c.learner_along, c.checked / 10) << "seed " << seed;
    }
}

TEST(LearningFactor, TlboLearnerModeLearnerStepsAlongTheDifferenceOfTwoLearners) {
    const auto inner = sphere(5);
    const std::size_t np = 8;
    const int its = 6;
    for (const std::uint64_t seed : {5ULL, 6ULL, 7ULL}) {
        const RecordingProblem rec(*inner);
        run("tlbo:np=8,r=learner", rec, seed, iterations(its));
        const Tally l = tally_tlbo_steps(rec, np, its);
        // Every learner step not clamped: its count of unclamped steps is not tallied apart, so
        // compare against the whole phase less the clamped ones, counted here.
        int unclamped = 0;
        for (std::size_t it = 0; it < static_cast<std::size_t>(its); ++it)
            for (std::size_t i = 0; i < np; ++i)
                unclamped += clamped(rec.points[np + it * 2 * np + np + i], rec.bounds()) ? 0 : 1;
        EXPECT_EQ(l.learner_along, unclamped) << "seed " << seed;
        EXPECT_GT(unclamped, 30) << "seed " << seed;
    }
}

// PSO starts from zero velocity, so in learner mode the first move is exactly c2 r2 (gbest - x),
// one r2 for every coordinate: a multiple in [0, 2) of gbest - x. Per coordinate it is not.
TEST(LearningFactor, PsoLearnerModeFirstMoveIsAMultipleOfTheWayToTheGlobalBest) {
    const Rosenbrock inner(4);
    const std::size_t np = 10;
    for (const bool per_learner : {true, false}) {
        int checked = 0;
        int multiples = 0;
        for (const std::uint64_t seed : {12ULL, 13ULL, 14ULL}) {
            const RecordingProblem rec(inner);
            run(std::string("pso:np=10") + (per_learner ? ",r=learner" : ""), rec, seed, iterations(1));
            ASSERT_EQ(rec.points.size(), 2 * np);
            std::size_t g = 0;
            for (std::size_t i = 1; i < np; ++i)
                if (rec.f(i) < rec.f(g))
                    g = i;
            for (std::size_t i = 0; i < np; ++i) {
                if (i == g || clamped(rec.points[np + i], inner.bounds()))
                    continue;
                ++checked;
                double t = 0.0;
                if (along(rec.points[np + i] - rec.points[i], rec.points[g] - rec.points[i],
                          rec.points[i].norm(), t) &&
                    t >= 0.0 && t < 2.0)
                    ++multiples;
            }
        }
        EXPECT_GT(checked, 5);
        if (per_learner)
            EXPECT_EQ(multiples, checked);
        else
            EXPECT_LT(multiples, checked / 4 + 1);
    }
}

} // namespace
} // namespace mhb::test
