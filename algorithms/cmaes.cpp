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
// Bound handling: a sample outside the box is redrawn up to 10 times (the draws cost no evaluation);
// if it is still outside, the Objective clamps it, and the update uses the clamped point that was
// actually evaluated.
// Restart criteria (Hansen's tutorial, appendix B.3, and pycma's defaults): TolFun 1e-12 on the
// range of the current and the last 10 + ceil(30 D / lambda) generations' best f, TolX 1e-12 * sigma0,
// condition number of C above 1e14, no effect of an axis or of a coordinate, a non-finite sigma.
// Evaluations: lambda per iteration (the first generation is iteration 0); a generation's offspring
// are evaluated as one batch (Objective::evaluate_batch).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"

namespace mhb {
namespace {

enum class Restarts { ipop, bipop, none };

constexpr long long kNoGenerationCap = std::numeric_limits<long long>::max();

// What one CMA-ES run starts from: its population size, its initial step size (a fraction of the
// box width) and the most generations it may take (BIPOP caps its small-population runs).
struct CmaRunSettings {
    int lambda;
    double sigma0;
    long long max_generations;
};

class CmaEs final : public Optimizer {
public:
    CmaEs(long long lambda, double sigma0, Restarts restarts)
        : lambda0_(lambda), sigma0_(sigma0), restarts_(restarts) {}

    std::string name() const override { return "cmaes"; }

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
            run_once(objective, rng, {static_cast<int>(lambda), sigma0_, kNoGenerationCap}, first);
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
        const auto spent_by = [&](const CmaRunSettings& settings) {
            const std::int64_t before = objective.evaluations();
            run_once(objective, rng, settings, first);
            return objective.evaluations() - before;
        };
        small_budget += spent_by({static_cast<int>(default_lambda), sigma0_, kNoGenerationCap});
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
                large_budget += spent_by({static_cast<int>(large_lambda), sigma0_, kNoGenerationCap});
            }
        }
    }

    // One CMA-ES run from a random mean until a stop criterion, the generation cap or the budget
    // ends it.
    void run_once(Objective& objective, Rng& rng, const CmaRunSettings& settings, bool& first) const {
        const int lambda = settings.lambda;
        const Eigen::Index n = objective.dimension();
        const double dn = static_cast<double>(n);
        const Box& box = objective.bounds();
        const Eigen::ArrayXd width = (box.upper - box.lower).array();

        // Selection and adaptation constants (tutorial, Table 1).
        const int mu = lambda / 2;
        Eigen::VectorXd w(mu);
        for (int i = 0; i < mu; ++i)
            w[i] = std::log((lambda + 1) / 2.0) - std::log(i + 1.0);
        w /= w.sum();
        const double mu_eff = 1.0 / w.squaredNorm();
        const double c_c = (4.0 + mu_eff / dn) / (dn + 4.0 + 2.0 * mu_eff / dn);
        const double c_s = (mu_eff + 2.0) / (dn + mu_eff + 5.0);
        const double c_1 = 2.0 / ((dn + 1.3) * (dn + 1.3) + mu_eff);
        const double c_mu =
            std::min(1.0 - c_1, 2.0 * (mu_eff - 2.0 + 1.0 / mu_eff) / ((dn + 2.0) * (dn + 2.0) + mu_eff));
        const double d_s = 1.0 + 2.0 * std::max(0.0, std::sqrt((mu_eff - 1.0) / (dn + 1.0)) - 1.0) + c_s;
        const double chi_n = std::sqrt(dn) * (1.0 - 1.0 / (4.0 * dn) + 1.0 / (21.0 * dn * dn));
        const auto eigen_gap = static_cast<long long>(std::max(1.0, 1.0 / ((c_1 + c_mu) * dn * 10.0)));

        Eigen::VectorXd m(n);
        for (Eigen::Index k = 0; k < n; ++k)
            m[k] = rng.uniform();
        double sigma = settings.sigma0;
        Eigen::VectorXd p_s = Eigen::VectorXd::Zero(n), p_c = Eigen::VectorXd::Zero(n);
        Eigen::MatrixXd c = Eigen::MatrixXd::Identity(n, n), b = Eigen::MatrixXd::Identity(n, n);
        Eigen::VectorXd diag_d = Eigen::VectorXd::Ones(n);
        Eigen::MatrixXd inv_sqrt_c = Eigen::MatrixXd::Identity(n, n);
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(n);

        Eigen::MatrixXd y(n, lambda); // steps (x - m) / sigma in normalised coordinates
        std::vector<double> f(static_cast<std::size_t>(lambda));
        std::vector<int> order(static_cast<std::size_t>(lambda));
        std::deque<double> best_history;
        const auto history_length = static_cast<std::size_t>(10 + std::ceil(30.0 * dn / lambda));
        Eigen::VectorXd z(n);
        std::vector<Eigen::VectorXd> x(static_cast<std::size_t>(lambda), Eigen::VectorXd::Zero(n));
        long long generation = 0;

        while (!objective.exhausted()) {
            // The lambda offspring are sampled first and evaluated as one batch (in parallel for
            // an expensive problem): no sample depends on an f of its generation.
            for (int j = 0; j < lambda; ++j) {
                Eigen::VectorXd yn(n);
                for (int attempt = 0; attempt < 10; ++attempt) {
                    for (Eigen::Index k = 0; k < n; ++k)
                        z[k] = rng.normal();
                    yn = m + sigma * (b * diag_d.cwiseProduct(z));
                    if ((yn.array() >= 0.0).all() && (yn.array() <= 1.0).all())
                        break;
                }
                x[static_cast<std::size_t>(j)] = box.lower + (yn.array() * width).matrix();
            }
            objective.evaluate_batch(x, f); // clamps the samples still outside
            for (int j = 0; j < lambda; ++j) {
                y.col(j) = ((x[static_cast<std::size_t>(j)] - box.lower).array() / width).matrix() - m;
                y.col(j) /= sigma;
            }
            if (first) {
                objective.initialised();
                first = false;
            } else {
                objective.end_iteration();
            }
            ++generation;

            std::iota(order.begin(), order.end(), 0);
            std::stable_sort(order.begin(), order.end(), [&](int a, int bb) {
                return f[static_cast<std::size_t>(a)] < f[static_cast<std::size_t>(bb)];
            });

            Eigen::VectorXd y_w = Eigen::VectorXd::Zero(n);
            for (int i = 0; i < mu; ++i)
                y_w += w[i] * y.col(order[static_cast<std::size_t>(i)]);
            m += sigma * y_w;

            p_s = (1.0 - c_s) * p_s + std::sqrt(c_s * (2.0 - c_s) * mu_eff) * (inv_sqrt_c * y_w);
            const double ps_norm = p_s.norm();
            const double h_s_threshold =
                (1.4 + 2.0 / (dn + 1.0)) * chi_n *
                std::sqrt(1.0 - std::pow(1.0 - c_s, 2.0 * static_cast<double>(generation)));
            const bool h_s = ps_norm < h_s_threshold;
            p_c = (1.0 - c_c) * p_c + (h_s ? std::sqrt(c_c * (2.0 - c_c) * mu_eff) : 0.0) * y_w;

            Eigen::MatrixXd rank_mu = Eigen::MatrixXd::Zero(n, n);
            for (int i = 0; i < mu; ++i) {
                const auto col = y.col(order[static_cast<std::size_t>(i)]);
                rank_mu.noalias() += w[i] * col * col.transpose();
            }
            const double delta_h = h_s ? 0.0 : c_c * (2.0 - c_c);
            c = (1.0 + c_1 * delta_h - c_1 - c_mu) * c + c_1 * p_c * p_c.transpose() + c_mu * rank_mu;
            sigma *= std::exp((c_s / d_s) * (ps_norm / chi_n - 1.0));

            if (generation % eigen_gap == 0) {
                c = 0.5 * (c + c.transpose()).eval();
                solver.compute(c);
                const Eigen::VectorXd eig = solver.eigenvalues().cwiseMax(1e-300);
                b = solver.eigenvectors();
                diag_d = eig.cwiseSqrt();
                inv_sqrt_c = b * diag_d.cwiseInverse().asDiagonal() * b.transpose();
            }

            // Stop criteria: end this run (and restart, if restarts are on).
            best_history.push_back(f[static_cast<std::size_t>(order[0])]);
            if (best_history.size() > history_length)
                best_history.pop_front();
            const auto [lo_f, hi_f] = std::minmax_element(f.begin(), f.end());
            const auto [lo_h, hi_h] = std::minmax_element(best_history.begin(), best_history.end());
            const bool tol_fun = best_history.size() == history_length &&
                                 std::max(*hi_f, *hi_h) - std::min(*lo_f, *lo_h) < 1e-12;
            const bool tol_x = (sigma * p_c.cwiseAbs().array() < 1e-12 * sigma0_).all() &&
                               (sigma * c.diagonal().cwiseSqrt().array() < 1e-12 * sigma0_).all();
            const double max_d = diag_d.maxCoeff(), min_d = diag_d.minCoeff();
            const bool ill_conditioned = max_d > 1e7 * min_d;
            const Eigen::Index axis = static_cast<Eigen::Index>(generation % n);
            const bool no_effect_axis =
                ((m + 0.1 * sigma * diag_d[axis] * b.col(axis)).array() == m.array()).all();
            const bool no_effect_coord =
                ((m.array() + 0.2 * sigma * c.diagonal().cwiseSqrt().array()) == m.array()).any();
            if (tol_fun || tol_x || ill_conditioned || no_effect_axis || no_effect_coord ||
                !std::isfinite(sigma) || sigma > 1e6 || generation >= settings.max_generations)
                return;
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
         1,
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
         }});
}

} // namespace mhb
