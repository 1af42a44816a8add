// `external:cmd=...`: an optimiser written as another program (any language), driven over the
// external protocol (README, "External programs (any language)"). The child drives, as run()
// does; mhbench's Objective counts every evaluation, so the child can neither evaluate outside
// the count nor past the budget.
//   mhbench -> describe (handshake.hpp), then
//              {"type":"start","dimension":D,"lower":[...],"upper":[...],"budget":{"evaluations":N,
//               "iterations":M},"seed":S,"parameters":{...}}  (seed: 64 bits from the run's Rng)
//   child   -> {"type":"eval","x":[[...],...]}        one point or a batch
//   mhbench -> {"type":"values","f":[...],"x":[[...],...],"evaluations":E,"remaining":R}
//              f and the repaired x of the points evaluated: all of them, or, for a batch that
//              crosses the end of the budget, exactly those that fit (then "stop" follows)
//   child   -> {"type":"iteration"}                   optional: the end of an iteration (no answer)
//   child   -> {"type":"done"}                        optional: it stops early (converged)
//   mhbench -> {"type":"stop"}                        the budget is spent: the child exits
// A child that exits before its budget is spent, hangs past `timeout`, or writes something else
// is killed with its process group and the run is a failed record carrying its last stderr
// lines: an optimiser's state cannot be restarted, so there is no retry here.
// Evaluations per iteration: what the child asks for.
#include <cstdint>
#include <stdexcept>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/text_excerpt.hpp"
#include "problems/external/child_link.hpp"
#include "problems/external/command.hpp"
#include "problems/external/handshake.hpp"
#include "problems/external/protocol_json.hpp"

namespace mhb {
namespace {

using external::ChildFault;
using external::ChildLink;
using Seconds = std::chrono::duration<double>;

class ExternalOptimizer final : public Optimizer {
public:
    ExternalOptimizer(external::CommonOptions common, Seconds timeout, BoundPolicy policy)
        : command_(std::move(common.command)), argv_(std::move(common.argv)),
          parameters_(std::move(common.parameters)), startup_timeout_(common.startup_timeout),
          timeout_(timeout), policy_(policy) {
        // Asked once here for the version it announces, which joins the identity of its runs.
        try {
            ChildLink link(argv_);
            version_ = external::describe(link, "optimizer", parameters_, startup_timeout_).version;
            link.finish(Seconds(0.0));
        } catch (const ChildFault& fault) {
            throw std::invalid_argument("external optimizer '" + command_ +
                                        "': " + external::with_stderr(fault));
        }
        identity_ = external::identity_facts(argv_, version_);
    }

    std::string name() const override { return "external"; }
    BoundPolicy bound_policy() const override { return policy_; }
    std::string identity_facts() const override { return identity_; }

    void run(Objective& objective, Rng& rng) const override {
        // The program reports its iterations only if it wants to: with a budget of iterations
        // alone, one that never does would never be stopped.
        if (!objective.budget().max_evaluations)
            throw std::runtime_error(
                "external optimizer '" + command_ +
                "': needs an evaluation budget (--evaluations N, beside --iterations "
                "if wanted): a program that never reports an iteration would never stop");
        const std::uint64_t seed = rng.next();
        try {
            ChildLink link(argv_);
            drive(link, objective, seed);
        } catch (const ChildFault& fault) {
            throw std::runtime_error("external optimizer '" + command_ +
                                     "': " + external::with_stderr(fault));
        }
    }

private:
    void drive(ChildLink& link, Objective& objective, std::uint64_t seed) const {
        const auto version = external::describe(link, "optimizer", parameters_, startup_timeout_).version;
        if (version != version_)
            throw ChildFault("it announced version " + version + " when the study started and " + version_ +
                                 " now",
                             link.stderr_tail());
        link.send(start_message(objective, seed));
        for (;;) {
            if (objective.exhausted()) {
                stop(link);
                return;
            }
            const std::string line = link.receive(timeout_);
            nlohmann::json message;
            std::string type;
            try {
                message = external::parse_message(line);
                type = external::message_type(message);
            } catch (const std::exception& e) {
                throw ChildFault(link.program() + ": " + e.what(), link.stderr_tail());
            }
            if (type == "eval") {
                evaluate(link, objective, message);
            } else if (type == "iteration") {
                objective.end_iteration();
            } else if (type == "initialised") {
                objective.initialised();
            } else if (type == "done") {
                link.finish(Seconds(1.0));
                return;
            } else {
                throw ChildFault(link.program() + ": unknown message type " + quoted_excerpt(type),
                                 link.stderr_tail());
            }
        }
    }

    std::string start_message(const Objective& objective, std::uint64_t seed) const {
        const Budget& budget = objective.budget();
        return R"({"type":"start","dimension":)" + std::to_string(objective.dimension()) + R"(,"lower":)" +
               external::json_array(objective.bounds().lower) + R"(,"upper":)" +
               external::json_array(objective.bounds().upper) + R"(,"budget":{"evaluations":)" +
               (budget.max_evaluations ? std::to_string(*budget.max_evaluations) : "null") +
               R"(,"iterations":)" +
               (budget.max_iterations ? std::to_string(*budget.max_iterations) : "null") + R"(},"seed":)" +
               std::to_string(seed) + R"(,"parameters":)" + external::json_parameters(parameters_) + "}";
    }

    // Evaluates the points that fit in the budget, in order, and answers with what was evaluated.
    static void evaluate(ChildLink& link, Objective& objective, const nlohmann::json& message) {
        std::vector<Eigen::VectorXd> points;
        try {
            const auto& x = message.at("x");
            if (!x.is_array() || x.empty())
                throw std::runtime_error("eval without points");
            const auto dimension = static_cast<std::size_t>(objective.dimension());
            for (const auto& point : x)
                points.push_back(external::read_vector(point, "a point", dimension));
        } catch (const std::exception& e) {
            throw ChildFault(link.program() + ": bad eval message: " + e.what(), link.stderr_tail());
        }
        const auto room = static_cast<std::size_t>(std::min<std::int64_t>(
            objective.remaining_evaluations(), static_cast<std::int64_t>(points.size())));
        points.resize(room);
        std::vector<double> f(room);
        const std::int64_t before = objective.evaluations();
        try {
            objective.evaluate_batch(points, f);
        } catch (const BudgetExhausted&) {
            // A target reached inside the batch: the points after it were not evaluated.
        }
        const auto done = static_cast<std::size_t>(objective.evaluations() - before);
        points.resize(done);
        f.resize(done);
        const std::int64_t remaining = objective.remaining_evaluations();
        try {
            link.send(R"({"type":"values","f":)" + external::json_array(f) + R"(,"x":)" +
                      external::json_points(points) + R"(,"evaluations":)" +
                      std::to_string(objective.evaluations()) + R"(,"remaining":)" +
                      (objective.budget().max_evaluations ? std::to_string(remaining) : "null") + "}");
        } catch (const ChildFault&) {
            // Its last answer, as for "stop": once the budget is spent the run is complete, and a
            // program that exits without reading all of that answer (it had what it needed) ended
            // nothing early.
            if (!objective.exhausted())
                throw;
        }
    }

    void stop(ChildLink& link) const {
        // Once the budget is spent nothing it says matters; a child that dies or ignores "stop"
        // is simply ended (the run is complete).
        try {
            link.send(R"({"type":"stop"})");
        } catch (const ChildFault&) {
        }
        link.finish(std::min(timeout_, Seconds(2.0)));
    }

    std::string command_;
    std::vector<std::string> argv_;
    std::map<std::string, std::string> parameters_;
    Seconds startup_timeout_;
    Seconds timeout_;
    BoundPolicy policy_;
    std::string version_;
    std::string identity_;
};

} // namespace

void register_external_optimizer(AlgorithmRegistry& registry) {
    registry.add(
        {"external", 1,
         "an optimiser written as another program (any language), over mhbench's JSON-lines protocol",
         "mhbench's external protocol (README, \"External programs (any language)\")",
         [] {
             auto parameters = external::common_parameters();
             parameters.push_back(ParameterInfo::real("timeout", 60, 0, 86400,
                                                      "seconds allowed for each message of the program")
                                      .open_below());
             parameters.push_back(ParameterInfo::choice(
                 "bounds", "clamp", {"clamp", "reflect", "none"},
                 "how mhbench repairs the points it is sent (the repaired points are returned)"));
             return parameters;
         }(),
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             external::CommonOptions common = external::common_options(p);
             const std::string& bounds = p.text("bounds");
             const BoundPolicy policy = bounds == "reflect" ? BoundPolicy::reflect
                                        : bounds == "none"  ? BoundPolicy::none
                                                            : BoundPolicy::clamp;
             return std::make_unique<ExternalOptimizer>(std::move(common), Seconds(p.real("timeout")),
                                                        policy);
         }});
}

} // namespace mhb
