// CMA-ES, the standard (mu/mu_w, lambda)-CMA-ES with rank-one and rank-mu covariance updates and
// cumulative step-size adaptation, exactly as in Hansen's tutorial (N. Hansen, "The CMA Evolution
// Strategy: A Tutorial", arXiv:1604.00772, 2016; the defaults of its Table 1 and the update
// equations of its Appendix A, positive weights only). Restarts from a new random mean after a stop
// criterion: IPOP (Auger and Hansen 2005, "A restart CMA evolution strategy with increasing
// population size", IEEE CEC 2005), lambda doubled at each restart; or BIPOP (Hansen 2009,
// "Benchmarking a BI-population CMA-ES on the BBOB-2009 function testbed", GECCO workshops),
// which interleaves IPOP's growing populations with short runs of small populations and small
// initial steps, each restart in the regime that has spent less (run_bipop below says exactly how).
// Not done here (nor in IPOP): pycma's maxiter stop, 100 + 150 (D + 3)^2 / sqrt(lambda) generations.
// BIPOP's published runs are BBOB-2009's (COCO's data archive), not at hand here; it is checked by
// its own rules (tests/unit/algorithms/cmaes_restarts_test.cpp), not against them.
//
// Coordinates are normalised to the unit box internally, y = (x - lower) / (upper - lower), so that
// sigma0 means the same on every problem (the PMSM parameters span 0.5 ohm and 0.01 H).
// Defaults: lambda = 4 + floor(3 ln D), mu = floor(lambda / 2), sigma0 = 0.3 of the box width
// (Hansen: about a quarter to a third of the search range), m0 uniform in the box.
// Bound handling: a sample outside the box is redrawn up to 10 times in all (the draws cost no
// evaluation; a generation's first draws come first, then the redraws); if it is still outside, the
// Objective clamps it, and the update uses the clamped point that was actually evaluated.
// The eigendecomposition of C is postponed by Hansen's rule in purecma (cma_run.cpp says which).
// Version 2 (issue 26): that rule, instead of the tutorial's, and the generation's linear algebra as
// matrix products; the same algorithm, other numbers for a given seed (version 1 decomposed C at
// every generation from D = 10 on).
// Restart criteria (Hansen's tutorial, appendix B.3, and pycma's defaults): TolFun 1e-12 on the
// range of the current and the last 10 + ceil(30 D / lambda) generations' best f, TolX 1e-12 * sigma0,
// condition number of C above 1e14, no effect of an axis or of a coordinate, a non-finite sigma.
// Evaluations: lambda per iteration (the first generation is iteration 0); a generation's offspring
// are evaluated as one batch (Objective::evaluate_batch).
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/cma_run.hpp"
#include "algorithms/population_limits.hpp"

namespace mhb {
namespace {

enum class Restarts { ipop, bipop, none };

class CmaEs final : public Optimizer {
public:
    CmaEs(long long lambda, double sigma0, Restarts restarts)
        : lambda0_(lambda), sigma0_(sigma0), restarts_(restarts) {}

    std::string name() const override { return "cmaes"; }

    // The first population's offspring and their steps, and the D x D matrices (C, its
    // eigenvectors, C^(-1/2) products): restarts that double lambda may still run out later.
    std::optional<std::string> refusal(Eigen::Index dimension) const override {
        const auto d = static_cast<double>(dimension);
        const double lambda =
            lambda0_ > 0 ? static_cast<double>(lambda0_) : 4.0 + std::floor(3.0 * std::log(d));
        return population_memory_refusal("cmaes", 2.0 * lambda + 4.0 * d, dimension, "lambda");
    }

    void run(Objective& objective, Rng& rng) const override {
        const Eigen::Index n = objective.dimension();
        const long long default_lambda =
            lambda0_ > 0 ? lambda0_ : 4 + static_cast<long long>(std::floor(3.0 * std::log(n)));
        bool first = true;
        if (restarts_ == Restarts::bipop) {
            run_bipop(objective, rng, default_lambda, first);
            return;
        }
        long long lambda = default_lambda;
        while (!objective.exhausted()) {
            cma::run_once(objective, rng, {static_cast<int>(lambda), sigma0_}, sigma0_, first);
            if (restarts_ == Restarts::none)
                return;
            lambda *= 2;
        }
    }

private:
    // BIPOP (Hansen 2009), as pycma's fmin(bipop=True) and Hansen's MATLAB code do it: the first run
    // with the default population, then each restart in the regime that has spent fewer evaluations
    // so far. The large regime is IPOP: lambda_def 2^i at the i-th large run, sigma0. The small
    // regime draws sigma0 0.01^U1 and lambda_def (lambda_large / lambda_def)^(U2^2) (rounded down),
    // where lambda_large is the last large run's population, and stops after
    // ceil(budget_large / (2 lambda)) generations, half the large regime's evaluations. The first
    // run is charged to the small regime (pycma's comment: "reproduced from Matlab"), so the first
    // restart is large.
    void run_bipop(Objective& objective, Rng& rng, long long default_lambda, bool& first) const {
        std::int64_t small_budget = 0, large_budget = 0;
        long long large_lambda = default_lambda;
        const auto spent_by = [&](const cma::RunSettings& settings) {
            const std::int64_t before = objective.evaluations();
            cma::run_once(objective, rng, settings, sigma0_, first);
            return objective.evaluations() - before;
        };
        small_budget += spent_by({static_cast<int>(default_lambda), sigma0_});
        while (!objective.exhausted()) {
            if (small_budget < large_budget) {
                const double sigma = sigma0_ * std::pow(0.01, rng.uniform());
                const double u = rng.uniform();
                const auto lambda_def = static_cast<double>(default_lambda);
                const auto lambda = static_cast<long long>(
                    std::floor(lambda_def * std::pow(static_cast<double>(large_lambda) / lambda_def, u * u)));
                const auto generations = static_cast<long long>(
                    std::ceil(0.5 * static_cast<double>(large_budget) / static_cast<double>(lambda)));
                small_budget += spent_by({static_cast<int>(lambda), sigma, generations});
            } else {
                large_lambda *= 2;
                large_budget += spent_by({static_cast<int>(large_lambda), sigma0_});
            }
        }
    }

    long long lambda0_;
    double sigma0_;
    Restarts restarts_;
};

Restarts restarts_from(const std::string& name) {
    if (name == "ipop")
        return Restarts::ipop;
    return name == "bipop" ? Restarts::bipop : Restarts::none;
}

} // namespace

void register_cmaes(AlgorithmRegistry& registry) {
    registry.add(
        {"cmaes",
         2,
         "CMA-ES (mu/mu_w, lambda) with rank-one and rank-mu updates and CSA, IPOP or BIPOP restarts; "
         "lambda evaluations per iteration",
         "Hansen (2016), The CMA Evolution Strategy: A Tutorial, arXiv:1604.00772; IPOP: Auger and Hansen "
         "(2005), IEEE CEC 2005; BIPOP: Hansen (2009), GECCO BBOB workshop",
         {ParameterInfo::integer("lambda", 0, 0, 1000000,
                                 "offspring per generation; 0 = 4 + floor(3 ln D) (Hansen 2016); else >= 2"),
          ParameterInfo::real("sigma0", 0.3, 0.0, 1.0,
                              "initial step size as a fraction of the box width (Hansen 2016: 1/4 to 1/3)")
              .open_below(),
          ParameterInfo::choice("restarts", "ipop", {"ipop", "bipop", "none"},
                                "after a stop criterion: restart with lambda doubled (IPOP, Auger and "
                                "Hansen 2005), alternate that with short small-population runs (BIPOP, "
                                "Hansen 2009), or end the run early (none)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             const long long lambda = p.integer("lambda");
             if (lambda == 1)
                 throw std::invalid_argument("cmaes: parameter 'lambda' = 1 is too small: give 0 (default) "
                                             "or at least 2 (mu = lambda / 2 parents)");
             return std::make_unique<CmaEs>(lambda, p.real("sigma0"), restarts_from(p.text("restarts")));
         }},
        {"CMA-ES", "restarts", {{"ipop", "CMA-ES (IPOP)"}, {"bipop", "CMA-ES (BIPOP)"}, {"none", "CMA-ES"}}});
}

} // namespace mhb
