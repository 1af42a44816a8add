// `external:cmd=...`: a problem computed by another program (any language) over the external
// protocol (README, "External programs (any language)"; messages in handshake.hpp and below).
//   mhbench -> {"type":"eval","x":[[x11,...],[x21,...],...]}
//   child   -> {"type":"values","f":[f1,f2,...]}
// A pool of up to `workers` child processes serves every run of the study: a model that is not
// thread-safe, or allows one instance per process, still runs in parallel across the runner's
// threads, and a batch (Objective::evaluate_batch) is split across the free workers.
//
// Faults (a child that exits, hangs past its timeout, writes a line that is not the answer, a NaN
// or the wrong count): the child is killed with its process group, the points of that message
// get the `on_failure` policy (+inf values, or a failed run), and the worker is started again at
// its next use. After `restarts` faults in a row of one worker the run fails whatever the policy,
// with the child's last stderr lines.
#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "problems/core/text_excerpt.hpp"
#include "problems/external/command.hpp"
#include "problems/external/handshake.hpp"
#include "problems/external/protocol_json.hpp"
#include "problems/external/spawner.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

using external::ChildFault;
using external::ChildLink;
using Seconds = std::chrono::duration<double>;

struct ExternalOptions : external::CommonOptions {
    std::size_t workers = 1;
    Seconds timeout{60.0}; // per evaluation: a message of k points is given k times this
    bool fail_on_fault = true;
    int restarts = 3;
};

class ExternalProblem final : public Problem {
public:
    explicit ExternalProblem(ExternalOptions options)
        : options_(std::move(options)), slots_(options_.workers) {
        // The first worker describes the problem and stays as worker 0.
        try {
            slots_[0].link = spawner_.start(options_.argv);
            description_ =
                external::describe(*slots_[0].link, "problem", options_.parameters, options_.startup_timeout);
        } catch (const ChildFault& fault) {
            throw std::invalid_argument("external problem '" + options_.command +
                                        "': " + external::with_stderr(fault));
        }
        description_.bounds.validate("external problem '" + options_.command + "'");
        identity_ = external::identity_facts(options_.argv, description_.version);
        for (std::size_t i = 0; i < slots_.size(); ++i)
            free_.push_back(i);
    }

    std::string name() const override { return "external"; }
    Eigen::Index dimension() const override { return description_.bounds.dimension(); }
    const Box& bounds() const override { return description_.bounds; }
    std::optional<KnownOptimum> known_optimum() const override { return description_.optimum; }
    std::vector<std::string> parameter_names() const override { return description_.names; }
    std::optional<Eigen::VectorXd> true_parameters() const override { return description_.truth; }
    std::vector<std::string> warnings() const override {
        // Allowed: a study of a box that misses the truth is a fair question, but worth saying.
        if (!description_.truth || description_.bounds.contains(*description_.truth))
            return {};
        return {"the truth it declares lies outside its box: no run can reach an error of 0 % "
                "(P_err_pct)"};
    }
    bool batch_evaluation() const override { return true; }
    std::string identity_facts() const override { return identity_; }

    double evaluate(const Eigen::VectorXd& x) const override {
        double f = 0.0;
        evaluate_many(std::span<const Eigen::VectorXd>(&x, 1), std::span<double>(&f, 1));
        return f;
    }

    void evaluate_many(std::span<const Eigen::VectorXd> x, std::span<double> f) const override {
        const std::size_t chunks = std::min(options_.workers, x.size());
        if (chunks <= 1) {
            exchange(x, f);
            return;
        }
        // One message per worker; each chunk waits for a worker of its own.
        const std::size_t size = (x.size() + chunks - 1) / chunks;
        std::vector<std::exception_ptr> errors(chunks);
        tbb::this_task_arena::isolate([&] {
            tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
                const std::size_t begin = c * size;
                const std::size_t count = std::min(size, x.size() - std::min(begin, x.size()));
                if (count == 0)
                    return;
                try {
                    exchange(x.subspan(begin, count), f.subspan(begin, count));
                } catch (...) {
                    errors[c] = std::current_exception();
                }
            });
        });
        for (const auto& error : errors)
            if (error)
                std::rethrow_exception(error);
    }

private:
    struct Slot {
        std::unique_ptr<ChildLink> link;
        int faults_in_a_row = 0;
    };

    // One message to one worker and its answer, with the fault policy.
    void exchange(std::span<const Eigen::VectorXd> x, std::span<double> f) const {
        const std::size_t index = acquire();
        Slot& slot = slots_[index];
        try {
            if (!slot.link) {
                slot.link = spawner_.start(options_.argv);
                const auto again =
                    external::describe(*slot.link, "problem", options_.parameters, options_.startup_timeout);
                if (again.version != description_.version || again.bounds.dimension() != dimension())
                    throw ChildFault("a restarted worker describes another problem (version " +
                                         again.version + ", dimension " +
                                         std::to_string(again.bounds.dimension()) + ")",
                                     slot.link->stderr_tail());
            }
            slot.link->send(R"({"type":"eval","x":)" + external::json_points(x) + "}");
            const std::string line = slot.link->receive(
                options_.timeout * static_cast<double>(std::max<std::size_t>(x.size(), 1)));
            read_values(*slot.link, line, f);
            slot.faults_in_a_row = 0;
            release(index);
        } catch (const ChildFault& fault) {
            // The child is in an unknown state: end it (and its group); the next use starts one.
            if (slot.link)
                slot.link->kill();
            slot.link.reset();
            const int faults = ++slot.faults_in_a_row;
            release(index);
            const std::string what =
                "external problem '" + options_.command + "': " + external::with_stderr(fault);
            if (faults > options_.restarts)
                throw std::runtime_error(what + " (" + std::to_string(faults) +
                                         " faults in a row of one worker: given up)");
            if (options_.fail_on_fault)
                throw std::runtime_error(what);
            std::fill(f.begin(), f.end(), std::numeric_limits<double>::infinity());
        } catch (...) {
            release(index);
            throw;
        }
    }

    // The answer to an eval message: values, one per point, none NaN.
    static void read_values(ChildLink& link, const std::string& line, std::span<double> f) {
        try {
            const nlohmann::json message = external::parse_message(line);
            if (external::message_type(message) != "values" || !message.contains("f"))
                throw std::runtime_error("answered eval with " + quoted_excerpt(line));
            const std::vector<double> values = external::read_numbers(message.at("f"), "f", f.size());
            for (std::size_t i = 0; i < values.size(); ++i) {
                if (std::isnan(values[i]))
                    throw std::runtime_error("returned NaN for point " + std::to_string(i + 1) + " of " +
                                             std::to_string(values.size()));
                f[i] = values[i];
            }
        } catch (const std::exception& e) {
            throw ChildFault(link.program() + ": " + e.what(), link.stderr_tail());
        }
    }

    std::size_t acquire() const {
        std::unique_lock<std::mutex> lock(mutex_);
        available_.wait(lock, [this] { return !free_.empty(); });
        // Started workers first, so that a pool of 8 for a study on 2 threads starts 2.
        auto pick = std::find_if(free_.begin(), free_.end(),
                                 [this](std::size_t i) { return slots_[i].link != nullptr; });
        if (pick == free_.end())
            pick = free_.begin();
        const std::size_t index = *pick;
        free_.erase(pick);
        return index;
    }

    void release(std::size_t index) const {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            free_.push_back(index);
        }
        available_.notify_one();
    }

    ExternalOptions options_;
    // Declared before slots_, so destroyed after them: its thread (which the children's
    // PR_SET_PDEATHSIG is tied to) outlives every child it forked.
    mutable external::Spawner spawner_;
    mutable std::vector<Slot> slots_; // each used by the thread that acquired it only
    mutable std::vector<std::size_t> free_;
    mutable std::mutex mutex_;
    mutable std::condition_variable available_;
    external::Description description_;
    std::string identity_;
};

} // namespace

void register_external_problem(ProblemRegistry& registry) {
    registry.add({"external", 1,
                  "a problem computed by another program (any language) over mhbench's JSON-lines protocol",
                  "mhbench's external protocol (README, \"External programs (any language)\")",
                  [] {
                      auto parameters = external::common_parameters();
                      parameters.push_back(ParameterInfo::integer(
                          "workers", 1, 1, 1024, "child processes per mhbench process (a pool)"));
                      parameters.push_back(
                          ParameterInfo::real(
                              "timeout", 60, 0, 86400,
                              "seconds allowed per evaluation (a message of k points gets k times this)")
                              .open_below());
                      parameters.push_back(ParameterInfo::choice(
                          "on_failure", "fail", {"fail", "inf"},
                          "the points of a failed message: fail the run, or take +inf"));
                      parameters.push_back(ParameterInfo::integer(
                          "restarts", 3, 0, 1000, "faults in a row of one worker before the run fails"));
                      return parameters;
                  }(),
                  [](const ParameterValues& p) -> std::unique_ptr<Problem> {
                      ExternalOptions o;
                      static_cast<external::CommonOptions&>(o) = external::common_options(p);
                      o.workers = static_cast<std::size_t>(p.integer("workers"));
                      o.timeout = Seconds(p.real("timeout"));
                      o.fail_on_fault = p.text("on_failure") == "fail";
                      o.restarts = static_cast<int>(p.integer("restarts"));
                      return std::make_unique<ExternalProblem>(std::move(o));
                  }});
}

} // namespace mhb
