// Shifted and rotated instances of the classic functions: the optimum moves where the instance
// says, the variant is exactly f(Q (x - c) + x*), the rotation is a rotation, the optimum stays the
// global one (random points never beat it), and instances are the same across runs and threads.
#include <Eigen/LU>
#include <gtest/gtest.h>
#include <thread>
#include <vector>

#include "problems/core/rng.hpp"
#include "problems/functions/classic_function.hpp"
#include "problems/functions/instance_transform.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

std::unique_ptr<Problem> make_function_instance(const std::string& spec) {
    return builtin_problems().create(spec);
}

Eigen::VectorXd random_point(const Box& box, Rng& rng) {
    Eigen::VectorXd x(box.dimension());
    for (Eigen::Index i = 0; i < x.size(); ++i)
        x[i] = rng.uniform(box.lower[i], box.upper[i]);
    return x;
}

TEST(ClassicInstances, ShiftMovesTheOptimumIntoTheCentralEightyPercentAsTheInstanceSays) {
    for (const auto& name : classic_function_names()) {
        const std::string noise = name == "quartic" ? ",noise=0" : "";
        for (const int instance : {1, 2, 7}) {
            const std::string spec = name + ":dim=10,shift=1,instance=" + std::to_string(instance) + noise;
            const auto p = make_function_instance(spec);
            const auto plain = make_function_instance(name + ":dim=10" + noise);
            const Eigen::VectorXd c = *p->known_optimum()->x;
            EXPECT_EQ(c, draw_shift(name, instance, p->bounds())) << spec;
            EXPECT_NE(c, *plain->known_optimum()->x) << spec;
            const Eigen::VectorXd centre = 0.5 * (p->bounds().lower + p->bounds().upper);
            const Eigen::VectorXd half = 0.5 * (p->bounds().upper - p->bounds().lower);
            EXPECT_TRUE(((c - centre).cwiseAbs().array() <= 0.8 * half.array()).all()) << spec;
            // f(c) is f* to the bit, and f* is the unshifted function's f*.
            EXPECT_EQ(p->evaluate(c), plain->known_optimum()->f) << spec;
            EXPECT_EQ(p->known_optimum()->f, plain->known_optimum()->f) << spec;
            // The variant is the function moved: f_shift(x) = f(x - c + x*).
            Rng rng(11);
            const Eigen::VectorXd own = *plain->known_optimum()->x;
            for (int k = 0; k < 5; ++k) {
                const Eigen::VectorXd x = random_point(p->bounds(), rng);
                EXPECT_EQ(p->evaluate(x), plain->evaluate((x - c) + own)) << spec;
            }
        }
    }
}

TEST(ClassicInstances, DifferentInstancesAndFamiliesGetDifferentShifts) {
    const Box box{Eigen::VectorXd::Constant(4, -5.0), Eigen::VectorXd::Constant(4, 5.0)};
    EXPECT_NE(draw_shift("rastrigin", 1, box), draw_shift("rastrigin", 2, box));
    EXPECT_NE(draw_shift("rastrigin", 1, box), draw_shift("ackley", 1, box));
    // The shift stream does not depend on the dimension: dimension 4 is a prefix of dimension 10.
    const Box wide{Eigen::VectorXd::Constant(10, -5.0), Eigen::VectorXd::Constant(10, 5.0)};
    EXPECT_EQ(draw_shift("rastrigin", 3, wide).head(4), draw_shift("rastrigin", 3, box));
}

TEST(ClassicInstances, RotationIsAProperRotationComputedOnce) {
    for (const Eigen::Index dim : {1, 2, 3, 10, 30, 100}) {
        for (const int instance : {1, 2, 3, 4, 5}) {
            const Eigen::MatrixXd q = draw_rotation("rastrigin", instance, dim);
            const double orthogonality =
                (q.transpose() * q - Eigen::MatrixXd::Identity(dim, dim)).cwiseAbs().maxCoeff();
            EXPECT_LT(orthogonality, 1e-12) << dim;
            EXPECT_NEAR(q.determinant(), 1.0, 1e-9) << "dim " << dim << " instance " << instance;
        }
    }
    EXPECT_NE(draw_rotation("rastrigin", 1, 5), draw_rotation("rastrigin", 2, 5));
}

TEST(ClassicInstances, RotatedVariantIsTheFunctionOfTheRotatedShiftedPoint) {
    for (const auto& name : classic_function_names()) {
        const std::string noise = name == "quartic" ? ",noise=0" : "";
        const std::string spec = name + ":dim=6,shift=1,rotate=1,instance=3" + noise;
        const auto p = make_function_instance(spec);
        const auto plain = make_function_instance(name + ":dim=6" + noise);
        const Eigen::VectorXd c = *p->known_optimum()->x;
        const Eigen::MatrixXd q = draw_rotation(name, 3, 6);
        const Eigen::VectorXd own = *plain->known_optimum()->x;
        EXPECT_EQ(c, draw_shift(name, 3, p->bounds())) << spec;
        EXPECT_EQ(p->evaluate(c), plain->known_optimum()->f) << spec;
        Rng rng(5);
        for (int k = 0; k < 5; ++k) {
            const Eigen::VectorXd x = random_point(p->bounds(), rng);
            const double expected = plain->evaluate(q * (x - c) + own);
            EXPECT_NEAR(p->evaluate(x), expected, 1e-12 * std::max(1.0, std::fabs(expected))) << spec;
        }
        // Rotation alone turns about the unshifted optimum.
        const auto turned = make_function_instance(name + ":dim=6,rotate=1,instance=3" + noise);
        EXPECT_EQ(*turned->known_optimum()->x, own) << name;
        EXPECT_EQ(turned->evaluate(own), plain->known_optimum()->f) << name;
    }
    // Rotation makes a separable function non-separable: moving one coordinate of a rotated
    // Rastrigin changes the value differently from the unrotated one.
    const auto flat = make_function_instance("rastrigin:dim=4,shift=1,instance=2");
    const auto turned = make_function_instance("rastrigin:dim=4,shift=1,rotate=1,instance=2");
    Eigen::VectorXd x = *turned->known_optimum()->x;
    x[0] += 0.3;
    EXPECT_GT(std::fabs(flat->evaluate(x) - turned->evaluate(x)), 1e-3);
}

TEST(ClassicInstances, NoRandomPointBeatsTheOptimumOfAnyVariant) {
    // Checks that moving the optimum never exposes a better region, e.g. Schwefel 2.26 beyond
    // +-500 (folded as in CEC 2014) or Rosenbrock's optimum near the box edge.
    for (const auto& name : classic_function_names()) {
        const std::string noise = name == "quartic" ? ",noise=0" : "";
        for (const std::string variant : {"", ",shift=1", ",shift=1,rotate=1", ",rotate=1"}) {
            for (const int instance : {1, 4}) {
                const std::string spec =
                    name + ":dim=5" + variant + ",instance=" + std::to_string(instance) + noise;
                const auto p = make_function_instance(spec);
                const double f_star = p->known_optimum()->f;
                Rng rng(static_cast<std::uint64_t>(instance) * 101);
                for (int k = 0; k < 2000; ++k)
                    ASSERT_GE(p->evaluate(random_point(p->bounds(), rng)), f_star) << spec;
            }
        }
    }
}

TEST(ClassicInstances, SameInstanceEverywhereAcrossRunsAndThreads) {
    const std::string spec = "rastrigin:dim=30,shift=1,rotate=1,instance=3";
    const auto reference = make_function_instance(spec);
    Rng rng(3);
    std::vector<Eigen::VectorXd> points;
    for (int k = 0; k < 20; ++k)
        points.push_back(random_point(reference->bounds(), rng));
    std::vector<double> expected;
    for (const auto& x : points)
        expected.push_back(reference->evaluate(x));
    // Each thread builds its own problem from the spec and shares one as well.
    std::vector<std::vector<double>> own(4);
    std::vector<std::vector<double>> shared(4);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            const auto p = make_function_instance(spec);
            for (const auto& x : points) {
                own[t].push_back(p->evaluate(x));
                shared[t].push_back(reference->evaluate(x));
            }
        });
    for (auto& th : threads)
        th.join();
    for (std::size_t t = 0; t < 4; ++t) {
        EXPECT_EQ(own[t], expected);
        EXPECT_EQ(shared[t], expected);
    }
}

TEST(ClassicInstances, InstancesArePinnedAcrossProcessesAndBuilds) {
    // Regression pins, recorded from this implementation when it was written: the generator is
    // our own (xoshiro256** with our normal draws, FNV-1a and SplitMix64 hashes), so these numbers
    // must come out the same in every process, build and platform. A change here changes every
    // published shifted/rotated instance: do it only on purpose.
    const Box box{Eigen::VectorXd::Constant(3, -5.12), Eigen::VectorXd::Constant(3, 5.12)};
    const Eigen::VectorXd c = draw_shift("rastrigin", 3, box);
    EXPECT_EQ(instance_seed("rastrigin", "shift", 3), 6347177507726588174u);
    EXPECT_DOUBLE_EQ(c[0], 2.9047161976328653);
    EXPECT_DOUBLE_EQ(c[1], 3.0242979609113765);
    EXPECT_DOUBLE_EQ(c[2], 2.8287659664866398);
    const auto p = make_function_instance("rastrigin:dim=3,shift=1,rotate=1,instance=3");
    EXPECT_NEAR(p->evaluate(Eigen::VectorXd::Zero(3)), 48.596103399780269, 1e-12 * 48.6);
}

} // namespace
} // namespace mhb
