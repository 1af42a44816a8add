// The paper's loops read literally (ARCHITECTURE.md section 9), checked on the points the algorithms
// actually evaluate (recorded in order by RecordingProblem): TLBO and ITLBO against a plain
// reference written from the papers; ITLBO's stepwise learning changes one component at a time and
// keeps it only if it improves; ITLBO's mutation evaluates lo + hi - X_i of the learner as
// learning left it; PSO's first move from zero velocity heads for the global best.
#include <cmath>
#include <gtest/gtest.h>

#include "tests/unit/algorithms/paper_algorithms_support.hpp"

namespace mhb::test {
namespace {

// Points must agree to a few ulps: the reference recomputes Mean from scratch for every learner
// where TLBO keeps a running sum, so the last bits may differ.
void expect_near_points(const Eigen::VectorXd& got, const Eigen::VectorXd& want, std::size_t n) {
    ASSERT_EQ(got.size(), want.size());
    for (Eigen::Index k = 0; k < got.size(); ++k)
        EXPECT_NEAR(got[k], want[k], 1e-12 * (1.0 + std::abs(want[k])))
            << "evaluation " << n << ", coordinate " << k;
}

// What the plain reference below does beyond TLBO: ITLBO's switches and options.
struct Switches {
    bool tutorial = false;
    bool stepwise = false;
    bool obl = false;
    double p = 0.1;
    bool obl_greedy = false;
    bool population_bounds = false;
    bool per_learner = false; // r=learner: one r (r1, r2) per learner and step
};

// A deliberately plain TLBO / ITLBO written from the papers (Rao et al. 2011; Li, Wang, Ji 2017,
// eqs. 5-10 and the pseudo-code of section 2.2.2) as ARCHITECTURE.md section 9 reads them: in place,
// index order; for every learner Mean is recomputed from the whole class as it is now and the
// teacher is the current best (lowest index among equals); clamping as the Objective's. Random
// draws in the order tlbo.cpp and itlbo.cpp document, for either learning factor (`r`), the
// mutation coins from the stream itlbo.cpp derives (a jumped copy of the run's stream). Returns
// every point evaluated, in order.
std::vector<Eigen::VectorXd> reference_run(const Problem& problem, std::uint64_t seed, int np, int iterations,
                                           Switches s) {
    Rng rng(seed);
    Rng coins = Rng(seed).jumped();
    const Box& box = problem.bounds();
    const Eigen::Index d = problem.dimension();
    const auto n = static_cast<std::size_t>(np);
    std::vector<Eigen::VectorXd> x;
    std::vector<double> f;
    std::vector<Eigen::VectorXd> points;
    const auto evaluate = [&](Eigen::VectorXd& y) {
        y = y.cwiseMax(box.lower).cwiseMin(box.upper);
        points.push_back(y);
        return problem.evaluate(y);
    };
    const auto greedy = [&](std::size_t i, Eigen::VectorXd& y) {
        const double fy = evaluate(y);
        if (fy < f[i]) {
            x[i] = y;
            f[i] = fy;
        }
    };
    for (std::size_t i = 0; i < n; ++i) {
        Eigen::VectorXd y(d);
        for (Eigen::Index k = 0; k < d; ++k)
            y[k] = box.lower[k] + rng.uniform() * (box.upper[k] - box.lower[k]);
        f.push_back(evaluate(y));
        x.push_back(y);
    }
    for (int it = 0; it < iterations; ++it) {
        for (std::size_t i = 0; i < n; ++i) { // teaching: eq. 6, or eq. 8 with tutorial
            const double tf = std::round(1.0 + rng.uniform());
            Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
            std::size_t t = 0;
            for (std::size_t m = 0; m < n; ++m) {
                mean += x[m] / np;
                if (f[m] < f[t])
                    t = m;
            }
            Eigen::VectorXd y(d);
            double r1 = 0.0;
            double r2 = 0.0;
            for (Eigen::Index k = 0; k < d; ++k) {
                if (k == 0 || !s.per_learner) {
                    r1 = rng.uniform();
                    r2 = s.tutorial ? rng.uniform() : 0.0;
                }
                y[k] = x[i][k] + r1 * (x[t][k] - tf * mean[k]) + r2 * (x[t][k] - x[i][k]);
            }
            greedy(i, y);
        }
        for (std::size_t i = 0; i < n; ++i) { // learning: eq. 7, or eq. 9 with stepwise
            const auto j = static_cast<std::size_t>(rng.below_except(n, i));
            const double r_i = s.per_learner ? rng.uniform() : 0.0;
            if (!s.stepwise) {
                const double direction = f[i] < f[j] ? 1.0 : -1.0;
                Eigen::VectorXd y(d);
                for (Eigen::Index k = 0; k < d; ++k)
                    y[k] = x[i][k] + (s.per_learner ? r_i : rng.uniform()) * direction * (x[i][k] - x[j][k]);
                greedy(i, y);
                continue;
            }
            for (Eigen::Index k = 0; k < d; ++k) {
                const double r = s.per_learner ? r_i : rng.uniform();
                const double direction = f[i] < f[j] ? 1.0 : -1.0;
                Eigen::VectorXd y = x[i];
                y[k] = x[i][k] + r * direction * (x[i][k] - x[j][k]);
                greedy(i, y);
            }
        }
        if (!s.obl) // mutation: eq. 10
            continue;
        Eigen::VectorXd lo = box.lower;
        Eigen::VectorXd hi = box.upper;
        if (s.population_bounds) {
            lo = x[0];
            hi = x[0];
            for (const auto& xm : x) {
                lo = lo.cwiseMin(xm);
                hi = hi.cwiseMax(xm);
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (!(coins.uniform() < s.p))
                continue;
            Eigen::VectorXd y = lo + hi - x[i];
            const double fy = evaluate(y);
            if (!s.obl_greedy || fy < f[i]) {
                x[i] = y;
                f[i] = fy;
            }
        }
    }
    return points;
}

void expect_same_points(const std::string& algorithm, const Problem& inner, std::uint64_t seed,
                        int iterations, const Switches& s) {
    const RecordingProblem recorder(inner);
    run(algorithm, recorder, seed, test::iterations(iterations));
    const auto want = reference_run(inner, seed, 6, iterations, s);
    ASSERT_EQ(recorder.points.size(), want.size()) << algorithm;
    for (std::size_t n = 0; n < want.size(); ++n)
        expect_near_points(recorder.points[n], want[n], n);
}

// TLBO and ITLBO evaluate the same points, in the same order, as the plain reference above (to
// 1e-12 relative): initialisation, per-learner Mean and teacher, in-place partners, greedy
// acceptance, and each of ITLBO's switches and options. NP = 6 on 3-D sphere and 4-D Rosenbrock.
TEST(PaperAlgorithmLoops, TlboAndItlboMatchAPlainReferenceImplementation) {
    const auto sphere3 = sphere(3);
    const Rosenbrock rosenbrock4(4);
    Switches all;
    all.tutorial = all.stepwise = all.obl = true;
    Switches greedy_half = all;
    greedy_half.p = 0.5;
    greedy_half.obl_greedy = true;
    Switches population_half = all;
    population_half.p = 0.5;
    population_half.population_bounds = true;
    Switches tutorial_mutation;
    tutorial_mutation.tutorial = tutorial_mutation.obl = true;
    tutorial_mutation.p = 0.3;
    for (const Problem* inner :
         {static_cast<const Problem*>(sphere3.get()), static_cast<const Problem*>(&rosenbrock4)})
        for (const std::uint64_t seed : {1ULL, 8ULL}) {
            expect_same_points("tlbo:np=6", *inner, seed, 8, Switches{});
            expect_same_points("itlbo:np=6", *inner, seed, 6, all);
            expect_same_points("itlbo:np=6,p=0.5,obl_greedy=on", *inner, seed, 6, greedy_half);
            expect_same_points("itlbo:np=6,p=0.5,obl_bounds=population", *inner, seed, 6, population_half);
            expect_same_points("itlbo:np=6,stepwise=off,p=0.3", *inner, seed, 6, tutorial_mutation);
        }
}

// The same in learner mode (`r=learner`): one r, or one r1 and one r2, per learner and step, for
// every coordinate; in stepwise learning one r_i per learner for every component.
TEST(PaperAlgorithmLoops, LearnerModeMatchesThePlainReferenceImplementation) {
    const auto sphere3 = sphere(3);
    const Rosenbrock rosenbrock4(4);
    Switches plain;
    plain.per_learner = true;
    Switches all = plain;
    all.tutorial = all.stepwise = all.obl = true;
    Switches tutorial_mutation = plain;
    tutorial_mutation.tutorial = tutorial_mutation.obl = true;
    tutorial_mutation.p = 0.3;
    Switches stepwise_only = plain;
    stepwise_only.stepwise = true;
    for (const Problem* inner :
         {static_cast<const Problem*>(sphere3.get()), static_cast<const Problem*>(&rosenbrock4)})
        for (const std::uint64_t seed : {1ULL, 8ULL}) {
            expect_same_points("tlbo:np=6,r=learner", *inner, seed, 8, plain);
            expect_same_points("itlbo:np=6,r=learner", *inner, seed, 6, all);
            expect_same_points("itlbo:np=6,stepwise=off,p=0.3,r=learner", *inner, seed, 6, tutorial_mutation);
            expect_same_points("itlbo:np=6,tutorial=off,obl=off,r=learner", *inner, seed, 6, stepwise_only);
        }
}

// The class as a test sees it from the recorded points alone: where each learner is and its
// fitness, starting from the first np points (the initialisation).
struct TrackedClass {
    std::vector<Eigen::VectorXd> x;
    std::vector<double> f;

    TrackedClass(const RecordingProblem& rec, std::size_t np) {
        for (std::size_t i = 0; i < np; ++i) {
            x.push_back(rec.points.at(i));
            f.push_back(rec.f(i));
        }
    }

    // One greedy phase of np points from `first` on, one per learner in index order (a teacher
    // phase, or eq. 7's learner phase): learner i moves to its point if that is better.
    void follow_greedy(const RecordingProblem& rec, std::size_t first) {
        for (std::size_t i = 0; i < x.size(); ++i)
            if (rec.f(first + i) < f[i]) {
                x[i] = rec.points[first + i];
                f[i] = rec.f(first + i);
            }
    }
};

// Eq. 9 and its pseudo-code: per learner, D evaluations, the k-th changing only component k of
// the learner as it is (earlier components kept only if they improved it). NP = 6, D = 5,
// three iterations of stepwise-only ITLBO, with exact equality of the untouched components.
TEST(PaperAlgorithmLoops, StepwiseLearningChangesOneComponentAndKeepsOnlyImprovements) {
    const Rosenbrock inner(5);
    const RecordingProblem rec(inner);
    const std::size_t np = 6;
    const auto d = static_cast<std::size_t>(inner.dimension());
    run("itlbo:np=6,tutorial=off,obl=off", rec, 4, iterations(3));
    ASSERT_EQ(rec.points.size(), np + 3 * (np + np * d));
    TrackedClass c(rec, np);
    auto& state = c.x;
    auto& f = c.f;
    std::size_t n = np;
    int kept = 0;
    for (int it = 0; it < 3; ++it) {
        c.follow_greedy(rec, n);
        n += np;
        for (std::size_t i = 0; i < np; ++i)
            for (std::size_t k = 0; k < d; ++k, ++n) {
                const Eigen::VectorXd& q = rec.points[n];
                for (std::size_t m = 0; m < d; ++m)
                    if (m != k) {
                        EXPECT_EQ(q[static_cast<Eigen::Index>(m)], state[i][static_cast<Eigen::Index>(m)])
                            << "evaluation " << n << " changed component " << m << ", not only " << k;
                    }
                if (rec.f(n) < f[i]) {
                    state[i] = q;
                    f[i] = rec.f(n);
                    ++kept;
                }
            }
    }
    EXPECT_GT(kept, 10); // the check above must have seen accepted and rejected components
    EXPECT_LT(kept, 3 * static_cast<int>(np * d));
}

// Eq. 10 with p = 1 (everyone mutated, the teacher included): the mutation step evaluates
// lo + hi - X_i for each learner as learning left it, in index order; with obl_greedy=off the
// learner becomes that point whatever its fitness, with on only if it is better. The bounds are
// the box's (static) or the class's min and max when the step begins (population).
TEST(PaperAlgorithmLoops, MutationEvaluatesTheOppositeOfEachLearner) {
    const Rosenbrock inner(4);
    const std::size_t np = 6;
    for (const bool greedy : {false, true})
        for (const bool population : {false, true}) {
            const RecordingProblem rec(inner);
            run(std::string("itlbo:np=6,tutorial=off,stepwise=off,p=1,obl_greedy=") +
                    (greedy ? "on" : "off") + ",obl_bounds=" + (population ? "population" : "static"),
                rec, 9, iterations(4));
            ASSERT_EQ(rec.points.size(), np + np * 4 * 3);
            TrackedClass c(rec, np);
            auto& state = c.x;
            auto& f = c.f;
            std::size_t n = np;
            int worse_taken = 0;
            for (int it = 0; it < 4; ++it) {
                c.follow_greedy(rec, n);      // teacher phase
                c.follow_greedy(rec, n + np); // learner phase (eq. 7)
                n += 2 * np;
                Eigen::VectorXd lo = inner.bounds().lower;
                Eigen::VectorXd hi = inner.bounds().upper;
                if (population) {
                    lo = state[0];
                    hi = state[0];
                    for (const auto& s : state) {
                        lo = lo.cwiseMin(s);
                        hi = hi.cwiseMax(s);
                    }
                }
                for (std::size_t i = 0; i < np; ++i, ++n) {
                    const Eigen::VectorXd opposite = lo + hi - state[i];
                    EXPECT_EQ(rec.points[n], opposite) << "evaluation " << n;
                    const double fo = rec.f(n);
                    if (!greedy || fo < f[i]) {
                        worse_taken += fo >= f[i] ? 1 : 0;
                        state[i] = opposite;
                        f[i] = fo;
                    }
                }
            }
            if (!greedy) {
                EXPECT_GT(worse_taken, 0) << "the paper's replacement must take worse points too";
            }
        }
}

// PSO starts from zero velocity (pso.cpp), so the first move is v = c2 r2 (gbest - x) with
// r2 in [0, 1): each coordinate moves from x towards the best initial point, by at most twice
// the distance (c2 = 2), and the best particle itself stays where it is.
TEST(PaperAlgorithmLoops, PsoFirstMoveFromZeroVelocityHeadsForTheGlobalBest) {
    const Rosenbrock inner(3);
    const RecordingProblem rec(inner);
    const std::size_t np = 8;
    run("pso:np=8", rec, 12, iterations(1));
    ASSERT_EQ(rec.points.size(), 2 * np);
    std::size_t g = 0;
    for (std::size_t i = 1; i < np; ++i)
        if (rec.f(i) < rec.f(g))
            g = i;
    const Eigen::VectorXd& best = rec.points[g];
    for (std::size_t i = 0; i < np; ++i) {
        const Eigen::VectorXd& x = rec.points[i];
        const Eigen::VectorXd& moved = rec.points[np + i];
        if (i == g) {
            EXPECT_EQ(moved, x);
            continue;
        }
        for (Eigen::Index k = 0; k < x.size(); ++k) {
            const double toward = best[k] - x[k];
            const double step = moved[k] - x[k];
            const double unclamped_max = x[k] + 2.0 * toward;
            const double clamped_max =
                std::clamp(unclamped_max, inner.bounds().lower[k], inner.bounds().upper[k]);
            EXPECT_GE(step * toward, 0.0) << "particle " << i << " moved away from gbest in " << k;
            EXPECT_LE(std::abs(step), std::abs(clamped_max - x[k]) + 1e-12) << "particle " << i;
        }
    }
}

} // namespace
} // namespace mhb::test
