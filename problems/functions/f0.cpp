// f0, the structural-bias test function (Kononova, Corne, De Wilde, Shneer, Caraffini, "Structural
// bias in population-based algorithms", Information Sciences 298, 2015): on [0, 1]^D, every
// evaluation returns a fresh U(0, 1) value whatever the point. No point is better than another,
// so an unbiased optimiser's final best points are uniform in the box; where they gather instead
// (the centre, the bounds) is the algorithm's own pull (results/analysis/structural_bias.hpp).
//
// Drawing at each evaluation is the one exception to "a problem draws nothing" (ARCHITECTURE.md
// section 4.1): the study's shared instance gives a hash of the point (what `mhbench eval` and
// plugin-check see), and each run evaluates its own instance from for_run(), whose values come
// from a stream of the run's seed alone, drawn in evaluation order, so a run is reproducible.
#include <cstdint>
#include <optional>

#include "problems/core/parameters.hpp"
#include "problems/core/rng.hpp"
#include "problems/functions/instance_transform.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

// Salts the run's seed so that f0's stream is not the optimiser's (which starts from the seed
// itself) nor its jumped copy: the values never correlate with the optimiser's draws.
const std::uint64_t f0_stream_salt = stable_hash("f0: the values of a run");

class UniformValueProblem final : public Problem {
public:
    UniformValueProblem(Eigen::Index dimension, std::optional<std::uint64_t> stream_seed)
        : box_{Eigen::VectorXd::Zero(dimension), Eigen::VectorXd::Ones(dimension)} {
        box_.validate("f0");
        if (stream_seed)
            stream_.emplace(*stream_seed);
    }

    std::string name() const override { return "f0"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }

    // A run's instance draws the next value of its stream; it serves one run on one thread (it
    // says no parallel or batch evaluation), so the values follow the order of evaluation.
    double evaluate(const Eigen::VectorXd& x) const override {
        return stream_ ? stream_->uniform() : hash_uniform(f0_stream_salt, x);
    }

    std::unique_ptr<Problem> for_run(std::uint64_t run_seed) const override {
        return std::make_unique<UniformValueProblem>(box_.dimension(), mix64(run_seed ^ f0_stream_salt));
    }

private:
    Box box_;
    mutable std::optional<Rng> stream_; // only in a run's own instance
};

} // namespace

void register_f0(ProblemRegistry& registry) {
    registry.add({"f0",
                  1,
                  "structural-bias test: f(x) ~ U(0, 1) afresh at each evaluation, on [0, 1]^dim, from "
                  "a stream of the run's seed",
                  "Kononova et al., Structural bias in population-based algorithms, Inf. Sci. 298 (2015)",
                  {ParameterInfo::integer("dim", 30, 1, 10000, "dimension")},
                  [](const ParameterValues& p) -> std::unique_ptr<Problem> {
                      return std::make_unique<UniformValueProblem>(
                          static_cast<Eigen::Index>(p.integer("dim")), std::nullopt);
                  }});
}

} // namespace mhb
