// Properties of every BBOB function in every dimension COCO uses and several instances, beyond
// the reference vectors: f(x_opt) = f_opt, x_opt in the box, no random point (inside or outside
// the box) below f_opt,
// f_opt on COCO's grid, instances that differ, the suite pattern, and thread-safety.
#include <cmath>
#include <gtest/gtest.h>
#include <set>
#include <thread>

#include "problems/bbob/bbob_random.hpp"
#include "problems/core/rng.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

std::string spec(int f, int dim, int instance) {
    return "bbob:f=" + std::to_string(f) + ",dim=" + std::to_string(dim) +
           ",instance=" + std::to_string(instance);
}

TEST(BbobProperties, OptimumIsAttainedInsideTheBoxAndNoRandomPointBeatsIt) {
    for (int f = 1; f <= 24; ++f)
        for (const int dim : {2, 3, 5, 10, 20, 40})
            for (const int instance : {1, 2, 5, 71}) {
                const std::string s = spec(f, dim, instance);
                const auto p = builtin_problems().create(s);
                EXPECT_EQ(p->dimension(), dim);
                EXPECT_TRUE((p->bounds().lower.array() == -5.0).all() &&
                            (p->bounds().upper.array() == 5.0).all());
                const auto opt = p->known_optimum();
                ASSERT_TRUE(opt && opt->x) << s;
                EXPECT_TRUE(p->bounds().contains(*opt->x)) << s;
                // f20's x_opt carries COCO's rounded constant 4.2096874637, hence the tolerance.
                EXPECT_NEAR(p->evaluate(*opt->x), opt->f, 1e-9) << s;
                Rng rng(static_cast<std::uint64_t>(1000 * f + dim + instance));
                // Half the points in the box, half in [-12, 12]^D: nothing beats f_opt outside the
                // box either (penalties, and f5's clipping beyond its corner).
                for (int k = 0; k < 200; ++k) {
                    const double reach = k % 2 == 0 ? 5.0 : 12.0;
                    Eigen::VectorXd x(dim);
                    for (Eigen::Index i = 0; i < dim; ++i)
                        x[i] = rng.uniform(-reach, reach);
                    ASSERT_GE(p->evaluate(x), opt->f - 1e-9) << s;
                }
            }
}

TEST(BbobProperties, OptimalValuesFollowCocosDefinition) {
    // f_opt = clamp(round(100 g1/g2) / 100, -1000, 1000) for two legacy normals: a multiple of 0.01.
    std::set<double> values;
    for (int f = 1; f <= 24; ++f)
        for (int instance = 1; instance <= 15; ++instance) {
            const double fopt = bbob::legacy_fopt(f, instance);
            EXPECT_LE(std::fabs(fopt), 1000.0);
            EXPECT_NEAR(fopt * 100.0, std::round(fopt * 100.0), 1e-6) << f << " " << instance;
            values.insert(fopt);
        }
    EXPECT_GT(values.size(), 300u); // instances differ
    // f4 and f18 take their f_opt from the seeds of f3 and f17 (COCO's rseed mapping).
    EXPECT_EQ(bbob::instance_seed(4, 2), 3 + 20000);
    EXPECT_EQ(bbob::instance_seed(18, 2), 17 + 20000);
    EXPECT_EQ(bbob::instance_seed(15, 3), 15 + 30000);
}

TEST(BbobProperties, LegacyGeneratorIsUniformAndRotationsOrthogonal) {
    const auto u = bbob::legacy_uniform(20000, 12345);
    double mean = 0.0;
    for (const double v : u) {
        ASSERT_GT(v, 0.0);
        ASSERT_LT(v, 1.0);
        mean += v;
    }
    mean /= static_cast<double>(u.size());
    EXPECT_NEAR(mean, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / 20000.0));
    for (const Eigen::Index dim : {2, 10, 40}) {
        const Eigen::MatrixXd r = bbob::legacy_rotation(1000003, dim);
        EXPECT_LT((r.transpose() * r - Eigen::MatrixXd::Identity(dim, dim)).cwiseAbs().maxCoeff(), 1e-12);
    }
}

TEST(BbobProperties, InstancesDiffer) {
    const auto a = builtin_problems().create(spec(15, 10, 1));
    const auto b = builtin_problems().create(spec(15, 10, 2));
    EXPECT_NE(*a->known_optimum()->x, *b->known_optimum()->x);
    EXPECT_NE(a->known_optimum()->f, b->known_optimum()->f);
    const Eigen::VectorXd x = Eigen::VectorXd::Constant(10, 0.5);
    EXPECT_NE(a->evaluate(x), b->evaluate(x));
}

TEST(BbobProperties, SuitePatternExpandsToOneProblemPerFunctionAndInstance) {
    const auto specs = builtin_problems().expand(Spec::parse("bbob:f=1-24,dim=10,instance=1-5"));
    ASSERT_EQ(specs.size(), 120u);
    std::set<std::string> distinct;
    for (const auto& s : specs) {
        distinct.insert(s.canonical());
        const auto p = builtin_problems().create(s);
        EXPECT_EQ(p->dimension(), 10);
    }
    EXPECT_EQ(distinct.size(), 120u);
    EXPECT_EQ(specs.front().canonical(), "bbob:dim=10,f=1,instance=1");
    EXPECT_EQ(specs.back().canonical(), "bbob:dim=10,f=24,instance=5");
    // Classic families expand their instances the same way.
    EXPECT_EQ(builtin_problems().expand(Spec::parse("rastrigin:dim=30,shift=1,instance=1-3")).size(), 3u);
}

TEST(BbobProperties, OneProblemSharedByManyThreadsGivesTheSameValues) {
    for (int f = 1; f <= 24; ++f) {
        const auto p = builtin_problems().create(spec(f, 20, 3));
        Rng rng(static_cast<std::uint64_t>(f));
        std::vector<Eigen::VectorXd> points;
        std::vector<double> expected;
        for (int k = 0; k < 10; ++k) {
            Eigen::VectorXd x(20);
            for (Eigen::Index i = 0; i < 20; ++i)
                x[i] = rng.uniform(-5.0, 5.0);
            expected.push_back(p->evaluate(x));
            points.push_back(x);
        }
        std::vector<std::vector<double>> got(3);
        std::vector<std::thread> threads;
        for (std::size_t t = 0; t < 3; ++t)
            threads.emplace_back([&, t] {
                for (const auto& x : points)
                    got[t].push_back(p->evaluate(x));
            });
        for (auto& th : threads)
            th.join();
        for (const auto& g : got)
            EXPECT_EQ(g, expected) << "f" << f;
    }
}

} // namespace
} // namespace mhb
