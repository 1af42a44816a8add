// NLopt's derivative-free algorithms as mhbench optimisers, through one adapter (S. G. Johnson,
// "The NLopt nonlinear-optimization package", https://github.com/stevengj/nlopt; the algorithm
// papers are listed in NLopt's documentation). `nlopt:algorithm=GN_CRS2_LM`, `nlopt:algorithm=
// GN_MLSL_LDS,local=LN_SBPLX`, `nlopt:algorithm=LN_BOBYQA`...
//
// What the adapter guarantees, beyond what NLopt does by itself:
// - An exact budget. NLopt's maxeval is not a strict maximum (some algorithms finish a population
//   first), so the callback force-stops NLopt as soon as the Objective's budget is spent, and any
//   call NLopt makes after that is answered with +inf without being evaluated or counted.
// - Independence from scheduling. NLopt's random generator is thread-local and, unseeded, seeded
//   from the time; each run seeds it from its own stream (nlopt::srand) before anything else.
// - Errors keep their message. NLopt's C++ wrapper turns an exception thrown by the objective into
//   a bare "nlopt failure"; the callback catches it itself, stores it and rethrows it after
//   optimize() returns.
// - Restarts. When an algorithm ends before the budget (a local method converging to xtol_rel or
//   ftol_rel, a global method finishing), it starts again from a point drawn uniformly in the box,
//   until the budget is spent. Local methods (LN_*) and MLSL's local optimiser stop at xtol_rel and
//   ftol_rel; the global methods get no tolerance and run until the budget ends them.
// Iterations: NLopt has no common notion of one, so an iteration is a block of `iteration_evals`
// evaluations (default 100, the cost of one TLBO iteration at the ITLBO paper's NP = 50); the
// first evaluation is iteration 0. Points are inside the box (NLopt gets it as bounds); the
// Objective clamps whatever is not.
#include <algorithm>
#include <climits>
#include <cmath>
#include <exception>
#include <nlopt.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"

namespace mhb {
namespace {

// The derivative-free NLopt algorithms that take box bounds and need no constraints, each with
// the short name a report gives it (the global methods first, then the local ones).
const std::vector<std::pair<std::string, std::string>>& nlopt_methods() {
    static const std::vector<std::pair<std::string, std::string>> methods = {
        {"GN_CRS2_LM", "CRS2-LM"},
        {"GN_ISRES", "ISRES"},
        {"GN_ESCH", "ESCH"},
        {"GN_DIRECT", "DIRECT"},
        {"GN_DIRECT_L", "DIRECT-L"},
        {"GN_DIRECT_L_RAND", "DIRECT-L (rand)"},
        {"GN_DIRECT_NOSCAL", "DIRECT (noscal)"},
        {"GN_DIRECT_L_NOSCAL", "DIRECT-L (noscal)"},
        {"GN_DIRECT_L_RAND_NOSCAL", "DIRECT-L (rand, noscal)"},
        {"GN_MLSL", "MLSL"},
        {"GN_MLSL_LDS", "MLSL-LDS"},
        {"LN_BOBYQA", "BOBYQA"},
        {"LN_NELDERMEAD", "Nelder-Mead"},
        {"LN_SBPLX", "Sbplx"},
        {"LN_COBYLA", "COBYLA"},
        {"LN_PRAXIS", "PRAXIS"},
        {"LN_NEWUOA_BOUND", "NEWUOA"}};
    return methods;
}

std::vector<std::string> all_algorithms() {
    std::vector<std::string> names;
    for (const auto& method : nlopt_methods())
        names.push_back(method.first);
    return names;
}

std::vector<std::string> local_algorithms() {
    std::vector<std::string> names;
    for (const auto& method : nlopt_methods())
        if (method.first.rfind("LN_", 0) == 0)
            names.push_back(method.first);
    return names;
}

bool is_local(const std::string& name) {
    return name.rfind("LN_", 0) == 0;
}
bool is_mlsl(const std::string& name) {
    return name.rfind("GN_MLSL", 0) == 0;
}

struct NloptSettings {
    std::string algorithm;
    std::string local; // MLSL's local optimiser
    double xtol_rel = 1e-8;
    double ftol_rel = 1e-12;
    long long population = 0; // 0: NLopt's default
    long long iteration_evals = 100;
};

// What the callback needs; lives on run()'s stack for the whole run.
struct CallbackState {
    Objective* objective = nullptr;
    nlopt::opt* opt = nullptr;
    Eigen::VectorXd x;
    long long iteration_evals = 100;
    long long evaluations_in_iteration = 0;
    bool initialised = false;
    bool stopped = false;
    std::exception_ptr error;

    void stop() {
        stopped = true;
        opt->force_stop();
    }
};

double nlopt_callback(unsigned n, const double* x, double* gradient, void* data) {
    (void)gradient; // derivative-free algorithms only
    auto& s = *static_cast<CallbackState*>(data);
    if (s.stopped || s.objective->exhausted()) {
        s.stop();
        return HUGE_VAL; // not evaluated, not counted
    }
    try {
        std::copy(x, x + n, s.x.data());
        const double f = s.objective->evaluate(s.x);
        if (!s.initialised) {
            s.objective->initialised();
            s.initialised = true;
        } else if (++s.evaluations_in_iteration == s.iteration_evals) {
            s.objective->end_iteration();
            s.evaluations_in_iteration = 0;
        }
        if (s.objective->exhausted())
            s.stop();
        return f;
    } catch (...) {
        s.error = std::current_exception();
        s.stop();
        return HUGE_VAL;
    }
}

nlopt::algorithm to_algorithm(const std::string& name) {
    const nlopt_algorithm a = nlopt_algorithm_from_string(name.c_str());
    if (static_cast<int>(a) < 0)
        throw std::invalid_argument("nlopt: unknown algorithm '" + name + "'");
    return static_cast<nlopt::algorithm>(a);
}

class NloptBaseline final : public Optimizer {
public:
    explicit NloptBaseline(NloptSettings settings) : s_(std::move(settings)) {}

    std::string name() const override { return "nlopt"; }

    void run(Objective& objective, Rng& rng) const override {
        nlopt::srand(static_cast<unsigned long>(rng.next()));
        const auto n = static_cast<unsigned>(objective.dimension());
        const Box& box = objective.bounds();
        const std::vector<double> lower(box.lower.data(), box.lower.data() + n);
        const std::vector<double> upper(box.upper.data(), box.upper.data() + n);

        CallbackState state;
        state.objective = &objective;
        state.x.resize(objective.dimension());
        state.iteration_evals = s_.iteration_evals;
        while (!objective.exhausted()) {
            nlopt::opt opt(to_algorithm(s_.algorithm), n);
            state.opt = &opt;
            state.stopped = false;
            opt.set_lower_bounds(lower);
            opt.set_upper_bounds(upper);
            if (s_.population > 0)
                opt.set_population(static_cast<unsigned>(s_.population));
            if (is_local(s_.algorithm)) {
                opt.set_xtol_rel(s_.xtol_rel);
                opt.set_ftol_rel(s_.ftol_rel);
            }
            if (is_mlsl(s_.algorithm)) {
                nlopt::opt local(to_algorithm(s_.local), n);
                local.set_xtol_rel(s_.xtol_rel);
                local.set_ftol_rel(s_.ftol_rel);
                opt.set_local_optimizer(local);
            }
            const std::int64_t remaining = objective.remaining_evaluations();
            if (remaining < INT_MAX)
                opt.set_maxeval(static_cast<int>(remaining));
            opt.set_min_objective(nlopt_callback, &state);

            const Eigen::VectorXd start = uniform_point(box, rng);
            std::vector<double> x(start.data(), start.data() + n);
            double f = 0.0;
            const std::int64_t before = objective.evaluations();
            try {
                opt.optimize(x, f);
            } catch (const nlopt::forced_stop&) {
                // Our own stop: the budget is spent, or the objective threw (rethrown below).
            } catch (const nlopt::roundoff_limited&) {
                // A local method can go no further: restart.
            } catch (const std::exception& e) {
                if (!state.error)
                    throw std::runtime_error("nlopt " + s_.algorithm + ": " + e.what());
            }
            state.opt = nullptr;
            if (state.error)
                std::rethrow_exception(state.error);
            if (objective.evaluations() == before)
                return; // NLopt ended without evaluating anything: restarting would not help
        }
    }

private:
    NloptSettings s_;
};

} // namespace

void register_nlopt(AlgorithmRegistry& registry) {
    registry.add(
        {"nlopt",
         1,
         "NLopt's derivative-free algorithms (CRS2, ISRES, ESCH, DIRECT, MLSL, BOBYQA, Nelder-Mead, Sbplx, "
         "COBYLA...) with an exact budget and random restarts; iteration = iteration_evals evaluations",
         "Johnson, The NLopt nonlinear-optimization package, https://github.com/stevengj/nlopt (v2.7)",
         {ParameterInfo::choice("algorithm", "GN_CRS2_LM", all_algorithms(),
                                "the NLopt algorithm, by its NLopt name"),
          ParameterInfo::choice("local", "LN_BOBYQA", local_algorithms(),
                                "local optimiser of GN_MLSL and GN_MLSL_LDS (only for them)"),
          ParameterInfo::real("xtol_rel", 1e-8, 0.0, 1.0,
                              "relative x tolerance at which a local search ends and restarts"),
          ParameterInfo::real("ftol_rel", 1e-12, 0.0, 1.0,
                              "relative f tolerance at which a local search ends and restarts"),
          ParameterInfo::integer("population", 0, 0, 1000000,
                                 "population of CRS2, ISRES, ESCH, MLSL; 0 = NLopt's default"),
          ParameterInfo::integer(
              "iteration_evals", 100, 1, 1000000000,
              "evaluations per iteration in the trace (100 = one TLBO iteration at NP = 50)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             NloptSettings s{p.text("algorithm"), p.text("local"),         p.real("xtol_rel"),
                             p.real("ftol_rel"),  p.integer("population"), p.integer("iteration_evals")};
             if (p.given("local") && !is_mlsl(s.algorithm))
                 throw std::invalid_argument("nlopt: parameter 'local' = " + s.local +
                                             " only applies to GN_MLSL and GN_MLSL_LDS, not to " +
                                             s.algorithm);
             if (is_local(s.algorithm) && s.xtol_rel == 0.0 && s.ftol_rel == 0.0)
                 throw std::invalid_argument("nlopt: " + s.algorithm +
                                             " needs 'xtol_rel' or 'ftol_rel' > 0 to end a local search");
             to_algorithm(s.algorithm); // this NLopt build must know it
             return std::make_unique<NloptBaseline>(std::move(s));
         }},
        {"NLopt", "algorithm", nlopt_methods()});
}

} // namespace mhb
