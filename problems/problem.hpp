// The Problem contract: what an optimisation problem is to mhbench. A problem computes and
// nothing else: evaluate() is const, thread-safe and has no hidden state (no counters, no file
// I/O, no random draws), so one instance is shared read-only by every run of a study. The one
// exception is a problem random per run (f0), which gives each run an instance of its own.
// Optimisers never see a Problem: they see the counted Objective (problems/objective.hpp).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace mhb {

// Closed box [lower, upper], one entry per dimension.
struct Box {
    Eigen::VectorXd lower;
    Eigen::VectorXd upper;

    [[nodiscard]] Eigen::Index dimension() const { return lower.size(); }
    [[nodiscard]] bool contains(const Eigen::VectorXd& x) const;
    // Throws std::invalid_argument unless lower < upper, both finite, sizes equal and > 0.
    void validate(const std::string& owner) const;
};

// A file a problem was read from, with the SHA-256 of the bytes it read: a study's run identity
// uses the content, not the path, so a file changed behind `data=` is noticed.
struct DataFile {
    std::string path;   // as given in the spec
    std::string sha256; // 64 lowercase hex digits
};

struct KnownOptimum {
    double f = 0.0;
    std::optional<Eigen::VectorXd> x; // where it is attained, if known
};

class Problem {
public:
    virtual ~Problem() = default;

    // Short family name, e.g. "sphere", "bbob", "pmsm".
    [[nodiscard]] virtual std::string name() const = 0;
    [[nodiscard]] virtual Eigen::Index dimension() const = 0;
    [[nodiscard]] virtual const Box& bounds() const = 0;
    // f(x) for x of size dimension(). Must be safe to call from many threads at once.
    [[nodiscard]] virtual double evaluate(const Eigen::VectorXd& x) const = 0;

    // The global optimum, where known (test functions; the least-squares optimum of a
    // steady-state identification problem). Tables show f - f* with it.
    [[nodiscard]] virtual std::optional<KnownOptimum> known_optimum() const { return std::nullopt; }

    // Names of the coordinates when they are physical parameters (e.g. Rs, Ld, Lq, psi);
    // empty for test functions.
    [[nodiscard]] virtual std::vector<std::string> parameter_names() const { return {}; }
    // The parameters that generated the data, where known, so errors can be reported.
    [[nodiscard]] virtual std::optional<Eigen::VectorXd> true_parameters() const { return std::nullopt; }

    // The files the problem's data came from, in the order given; empty for problems that read
    // none (test functions, simulated drives).
    [[nodiscard]] virtual std::vector<DataFile> data_files() const { return {}; }

    // What a user should know about this instance before trusting its results, one sentence
    // each (e.g. the optimum lies on a face of the search box); printed when a study starts.
    [[nodiscard]] virtual std::vector<std::string> warnings() const { return {}; }

    // True when one evaluation costs a simulation, so that a population is worth evaluating in
    // parallel inside a run (Objective::evaluate_batch); cheap functions say false.
    [[nodiscard]] virtual bool parallel_evaluation() const { return false; }

    // True when many points cost much less in one call than one by one (an external program:
    // one message for a batch); Objective::evaluate_batch then hands the points that fit in the
    // budget to evaluate_many() at once.
    [[nodiscard]] virtual bool batch_evaluation() const { return false; }
    // f[i] = evaluate(x[i]) for every i (sizes equal); the default is that loop. Like evaluate():
    // const and safe to call from many threads at once.
    virtual void evaluate_many(std::span<const Eigen::VectorXd> x, std::span<double> f) const;

    // What determines this problem's values beyond its spec and data files, as one line that
    // joins the identity of its runs: for an external program, the SHA-256 of its code and the
    // version it announces (problems/external/command.hpp). Empty for in-process problems, so
    // that their run identities are unchanged.
    [[nodiscard]] virtual std::string identity_facts() const { return {}; }

    // The instance one run evaluates, for a problem whose values are random per run (f0: a fresh
    // uniform value at each evaluation). It draws from a stream of `run_seed` alone, independent of
    // the optimiser's, serves that run only (one thread; parallel and batch evaluation off, so
    // values are drawn in evaluation order) and may keep state in evaluate(). nullptr, the
    // default, means the shared instance serves every run (ARCHITECTURE.md section 4.1).
    [[nodiscard]] virtual std::unique_ptr<Problem> for_run(std::uint64_t run_seed) const {
        (void)run_seed;
        return nullptr;
    }
};

} // namespace mhb
