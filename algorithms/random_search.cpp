// Pure random search: independent uniform samples in the box, the best one kept (Brooks 1958,
// "A discussion of random methods for seeking maxima"; Rastrigin 1963, "The convergence of the
// random search method in the extremal control of a many parameter system").
// It learns nothing from what it has seen, so it is the floor every optimiser must clear: an
// algorithm that does not beat it on a problem has not shown it can exploit that problem.
//
// Parameters: batch = evaluations per iteration (default 50, the paper's population size, so
// that at equal iterations random search spends what PSO spends).
// Evaluations: batch for the initialisation (iteration 0), then batch per iteration.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"

namespace mhb {
namespace {

class RandomSearch final : public Optimizer {
public:
    explicit RandomSearch(long long batch) : batch_(batch) {}

    std::string name() const override { return "random-search"; }

    void run(Objective& objective, Rng& rng) const override {
        std::vector<Eigen::VectorXd> points;
        std::vector<double> f;
        sample_batch(objective, rng, points, f);
        objective.initialised();
        while (!objective.exhausted()) {
            sample_batch(objective, rng, points, f);
            objective.end_iteration();
        }
    }

private:
    // Points evaluated per call of evaluate_batch at most: bounds the memory of a large `batch`.
    static constexpr long long chunk_ = 256;

    // The Objective keeps the best point, so a sample needs nothing else done with it. Samples are
    // drawn and evaluated in chunks (in parallel for an expensive problem), never more than the
    // budget has room for, or one when it has none (whose evaluation ends the run): so the draws
    // are those of sampling one point at a time (unless a target ends the run inside a chunk).
    void sample_batch(Objective& objective, Rng& rng, std::vector<Eigen::VectorXd>& points,
                      std::vector<double>& f) const {
        for (long long left = batch_; left > 0;) {
            const long long room = std::max<std::int64_t>(1, objective.remaining_evaluations());
            const auto n = static_cast<std::size_t>(std::min({left, chunk_, room}));
            points.resize(n);
            f.resize(n);
            for (auto& x : points)
                x = uniform_point(objective.bounds(), rng);
            objective.evaluate_batch(points, f);
            left -= static_cast<long long>(n);
        }
    }

    long long batch_;
};

} // namespace

void register_random_search(AlgorithmRegistry& registry) {
    registry.add(
        {"random-search",
         1,
         "pure random search: uniform samples in the box, the best kept; the baseline to beat",
         "Brooks (1958), Oper. Res. 6(2); Rastrigin (1963), Autom. Remote Control 24",
         {ParameterInfo::integer("batch", 50, 1, 1000000000,
                                 "evaluations per iteration (default 50 = the paper's population size)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             return std::make_unique<RandomSearch>(p.integer("batch"));
         }},
        {"Random search"});
}

} // namespace mhb
