// The paper's algorithms (TLBO, ITLBO of Li, Wang, Ji 2017, PSO): ITLBO with its switches off
// is TLBO bit for bit; evaluations per iteration follow the formulas of ARCHITECTURE.md section 9;
// each switch changes the run; runs are reproducible; bad parameters are clear errors.
#include <gtest/gtest.h>
#include <stdexcept>

#include "tests/unit/algorithms/paper_algorithms_support.hpp"

namespace mhb::test {
namespace {

constexpr const char* itlbo_all_off = "itlbo:tutorial=off,stepwise=off,obl=off";

// ARCHITECTURE.md section 9: "With all three switches off ITLBO must be TLBO, bit for bit, for the
// same seed". Checked on a separable and a non-separable problem, with budgets that end at an
// iteration boundary and in the middle of a phase, for several seeds and populations, and for
// both learning factors (`r=coordinate`, the default, and `r=learner`).
TEST(PaperAlgorithms, ItlboWithAllSwitchesOffIsTlboBitForBit) {
    const auto sphere10 = sphere(10);
    const Rosenbrock rosenbrock5(5);
    const Problem* problems[] = {sphere10.get(), &rosenbrock5};
    const Budget budgets[] = {iterations(40), evaluations(1234)};
    for (const Problem* problem : problems)
        for (const Budget& budget : budgets)
            for (const std::uint64_t seed : {1ULL, 7ULL, 2024ULL})
                for (const std::string np : {"50", "7"})
                    for (const std::string r : {"", ",r=coordinate", ",r=learner"}) {
                        const Outcome tlbo = run("tlbo:np=" + np + r, *problem, seed, budget);
                        const Outcome itlbo =
                            run(std::string(itlbo_all_off) + ",np=" + np + r, *problem, seed, budget);
                        EXPECT_TRUE(identical(tlbo, itlbo))
                            << problem->name() << " seed " << seed << " np " << np << r << ": tlbo "
                            << tlbo.best_f << ", itlbo " << itlbo.best_f;
                        EXPECT_GT(tlbo.iterations_trace.size(), 1u);
                    }
}

// Evaluations recorded at the end of every iteration, as differences.
std::vector<std::int64_t> evaluations_per_iteration(const Outcome& o) {
    std::vector<std::int64_t> out;
    for (std::size_t t = 1; t < o.iterations_trace.size(); ++t)
        out.push_back(o.iterations_trace[t].evaluations - o.iterations_trace[t - 1].evaluations);
    return out;
}

void expect_costs(const std::string& algorithm, const Problem& problem, std::int64_t np,
                  std::int64_t per_iteration) {
    const Outcome o = run(algorithm, problem, 3, iterations(12));
    ASSERT_EQ(o.iterations_trace.size(), 13u) << algorithm;
    EXPECT_EQ(o.iterations_trace[0].evaluations, np) << algorithm << ": initialisation";
    for (const std::int64_t n : evaluations_per_iteration(o))
        EXPECT_EQ(n, per_iteration) << algorithm;
}

// The formulas of ARCHITECTURE.md section 9 (NP = 30, D = 10): PSO NP, TLBO 2 NP, ITLBO NP (teacher)
// + NP*D (stepwise) or NP (eq. 7) + one per mutation; p = 0 mutates no one, p = 1 everyone.
TEST(PaperAlgorithms, EvaluationsPerIterationFollowTheFormulas) {
    const auto p = sphere(10);
    expect_costs("pso:np=30", *p, 30, 30);
    expect_costs("tlbo:np=30", *p, 30, 60);
    expect_costs("itlbo:np=30,stepwise=off,obl=off", *p, 30, 60);
    expect_costs("itlbo:np=30,obl=off", *p, 30, 30 + 300);
    expect_costs("itlbo:np=30,p=0", *p, 30, 30 + 300);
    expect_costs("itlbo:np=30,p=1", *p, 30, 30 + 300 + 30);
    expect_costs("itlbo:np=30,p=1,obl_greedy=on", *p, 30, 30 + 300 + 30);
    expect_costs("itlbo:np=30,p=1,obl_bounds=population", *p, 30, 30 + 300 + 30);
    expect_costs("itlbo:np=30,stepwise=off,p=1", *p, 30, 30 + 30 + 30);
    expect_costs("itlbo:np=30,tutorial=off,stepwise=off,p=0", *p, 30, 60);
    // The learning factor changes the draws, never the evaluations.
    expect_costs("pso:np=30,r=learner", *p, 30, 30);
    expect_costs("tlbo:np=30,r=learner", *p, 30, 60);
    expect_costs("itlbo:np=30,stepwise=off,obl=off,r=learner", *p, 30, 60);
    expect_costs("itlbo:np=30,obl=off,r=learner", *p, 30, 30 + 300);
    expect_costs("itlbo:np=30,p=0,r=learner", *p, 30, 30 + 300);
    expect_costs("itlbo:np=30,p=1,r=learner", *p, 30, 30 + 300 + 30);
    expect_costs("itlbo:np=30,stepwise=off,p=1,r=learner", *p, 30, 30 + 30 + 30);
}

// With p = 0.1 the mutations per iteration are Binomial(NP, 0.1). NP = 50, D = 4 (the paper's
// sizes), 200 iterations: the total is Binomial(10000, 0.1), mean 1000, sd 30; the test allows
// 5 sd either way, and every iteration must cost between NP + NP*D and that plus NP.
TEST(PaperAlgorithms, MutationsAtTheDefaultProbabilityAreAboutOneInTen) {
    const auto p = sphere(4);
    const Outcome o = run("itlbo", *p, 11, iterations(200));
    std::int64_t mutations = 0;
    for (const std::int64_t n : evaluations_per_iteration(o)) {
        EXPECT_GE(n, 50 + 200);
        EXPECT_LE(n, 50 + 200 + 50);
        mutations += n - (50 + 200);
    }
    EXPECT_GT(mutations, 850);
    EXPECT_LT(mutations, 1150);
}

// Each of ITLBO's switches, alone, changes the run away from TLBO's (ARCHITECTURE.md section 9: three
// independent switches); and the OBL options each change it too.
TEST(PaperAlgorithms, EachSwitchAloneChangesTheRun) {
    const auto p = sphere(10);
    const Rosenbrock r(5);
    for (const Problem* problem : {static_cast<const Problem*>(p.get()), static_cast<const Problem*>(&r)}) {
        const Outcome tlbo = run("tlbo", *problem, 5, iterations(30));
        for (const char* alone :
             {"itlbo:stepwise=off,obl=off", "itlbo:tutorial=off,obl=off", "itlbo:tutorial=off,stepwise=off"})
            EXPECT_FALSE(identical(tlbo, run(alone, *problem, 5, iterations(30)))) << alone;
        const Outcome paper = run("itlbo:p=0.3", *problem, 5, iterations(30));
        for (const char* variant : {"itlbo:p=0.3,obl_greedy=on", "itlbo:p=0.3,obl_bounds=population"})
            EXPECT_FALSE(identical(paper, run(variant, *problem, 5, iterations(30)))) << variant;
    }
}

// The mutation coin flips have a stream of their own (itlbo.cpp: a jumped copy of the run's
// stream), so p = 0 is the same run as obl=off, whatever the other switches and learning factor.
TEST(PaperAlgorithms, OblWithZeroProbabilityIsOblOff) {
    const auto p = sphere(6);
    const Rosenbrock r(4);
    for (const Problem* problem : {static_cast<const Problem*>(p.get()), static_cast<const Problem*>(&r)})
        for (const std::string others : {"", "tutorial=off,", "stepwise=off,", "tutorial=off,stepwise=off,"})
            for (const std::string factor : {"", "r=learner,"})
                for (const std::uint64_t seed : {2ULL, 3ULL}) {
                    const Outcome off =
                        run("itlbo:" + others + factor + "obl=off", *problem, seed, iterations(25));
                    const Outcome zero =
                        run("itlbo:" + others + factor + "p=0", *problem, seed, iterations(25));
                    EXPECT_TRUE(identical(off, zero)) << others << factor << " seed " << seed;
                }
}

// Same seed, same run (bit for bit); another seed, another run.
TEST(PaperAlgorithms, SameSeedSameRunOtherSeedOtherRun) {
    const Rosenbrock r(5);
    for (const char* algorithm : {"tlbo", "itlbo", "pso", "itlbo:obl_bounds=population,obl_greedy=on"}) {
        const Outcome a = run(algorithm, r, 42, evaluations(3000));
        const Outcome b = run(algorithm, r, 42, evaluations(3000));
        const Outcome c = run(algorithm, r, 43, evaluations(3000));
        EXPECT_TRUE(identical(a, b)) << algorithm;
        EXPECT_FALSE(identical(a, c)) << algorithm;
        EXPECT_NE(a.best_f, c.best_f) << algorithm;
        EXPECT_EQ(a.evaluations, 3000) << algorithm;
    }
}

// A bad value names the component, the parameter and its allowed range (CONTRIBUTING.md: "pso:
// parameter 'w' = 1.3 is outside [0, 1]").
TEST(PaperAlgorithms, BadParametersAreClearErrors) {
    const auto message = [](const std::string& spec) -> std::string {
        try {
            static_cast<void>(builtin_algorithms().create(spec));
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "(no error)";
    };
    EXPECT_EQ(message("tlbo:np=1"), "tlbo: parameter 'np' = 1 is outside [2, 100000]");
    EXPECT_EQ(message("itlbo:np=0"), "itlbo: parameter 'np' = 0 is outside [2, 100000]");
    EXPECT_EQ(message("pso:np=1"), "pso: parameter 'np' = 1 is outside [2, 100000]");
    EXPECT_EQ(message("pso:w=1.3"), "pso: parameter 'w' = 1.3 is outside [0, 1]");
    EXPECT_EQ(message("pso:c1=-1"), "pso: parameter 'c1' = -1 is outside [0, 4]");
    EXPECT_EQ(message("itlbo:p=1.5"), "itlbo: parameter 'p' = 1.5 is outside [0, 1]");
    EXPECT_EQ(message("itlbo:obl_bounds=box"),
              "itlbo: parameter 'obl_bounds' = box is not one of {static, population}");
    EXPECT_EQ(message("itlbo:tutorial=maybe"),
              "itlbo: parameter 'tutorial' = maybe is not one of on/off, true/false, yes/no, 1/0");
    EXPECT_EQ(message("tlbo:tutorial=on"), "tlbo: unknown parameter 'tutorial'; known: np, r");
    for (const char* algorithm : {"tlbo", "itlbo", "pso"})
        EXPECT_EQ(message(std::string(algorithm) + ":r=particle"),
                  std::string(algorithm) + ": parameter 'r' = particle is not one of {coordinate, learner}");
    EXPECT_NE(message("pso:inertia=0.7").find("pso: unknown parameter 'inertia'; known: np, w, c1, c2"),
              std::string::npos);
}

TEST(PaperAlgorithms, NamesAndReferences) {
    const auto& registry = builtin_algorithms();
    EXPECT_NE(registry.find("itlbo").summary.find("Li, Wang, Ji (2017)"), std::string::npos);
    EXPECT_NE(registry.find("itlbo").reference.find("Li, Wang, Ji (2017)"), std::string::npos);
    EXPECT_NE(registry.find("tlbo").reference.find("Rao"), std::string::npos);
    EXPECT_EQ(registry.create("itlbo")->name(), "itlbo");
    EXPECT_EQ(registry.create("tlbo")->name(), "tlbo");
    EXPECT_EQ(registry.create("pso")->name(), "pso");
}

} // namespace
} // namespace mhb::test
