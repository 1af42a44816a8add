// The Bayesian signed-rank tests against the reference (bayesian_comparisons.hpp) and their CSVs.
#include "results/analysis/bayesian_comparisons.hpp"

#include <algorithm>
#include <oneapi/tbb/parallel_for.h>

#include "problems/core/rng.hpp"              // stable_hash, mix64: a test's seed from its names
#include "results/analysis/run_precision.hpp" // compared_value: the scale runs are compared on
#include "results/analysis/statistics.hpp"
#include "results/store/csv.hpp"

namespace mhb {

namespace {

BayesianSignedRankOptions test_options(const std::string& problem, const std::string& algorithm,
                                       const std::string& reference, double rope, std::size_t kept_samples) {
    BayesianSignedRankOptions options;
    options.rope = rope;
    options.seed = mix64(stable_hash(problem + '\n' + algorithm + '\n' + reference));
    options.kept_samples = kept_samples;
    return options;
}

std::optional<BayesianComparison> on_problem(const StudyIndex& index, const std::string& problem,
                                             const std::string& algorithm, const std::string& reference,
                                             const BayesianRope& rope, std::size_t kept_samples) {
    BayesianComparison c;
    c.problem = problem;
    c.algorithm = algorithm;
    c.paired = index.paired(problem);
    const RunGroup& ref = *index.find(problem, reference);
    const RunGroup& other = *index.find(problem, algorithm);
    c.log10_gap = ref.optimum_known() && other.optimum_known();
    c.rope = c.log10_gap ? std::optional<double>(rope.log10_gap) : rope.raw;
    if (!c.paired)
        return c;
    // The log10 gap where the problem knows f* (then every run of both does), else f.
    const PairedValues v = paired_values(ref, other, [](const RunRecord& r) { return compared_value(r); });
    if (v.x.empty())
        return std::nullopt;
    c.result =
        bayesian_signed_rank(paired_differences(v.x, v.y),
                             test_options(problem, algorithm, reference, c.rope.value_or(0.0), kept_samples));
    return c;
}

double median_value(const RunGroup& g) {
    std::vector<double> values;
    for (const RunRecord* r : g.runs)
        values.push_back(compared_value(*r)); // the log10 gap: every run knows f*
    return median_of(values);
}

// Across problems: per-problem medians of the log10 gap, paired by problem.
std::optional<BayesianComparison> across_problems(const StudyIndex& index, const std::string& algorithm,
                                                  const std::string& reference, const BayesianRope& rope,
                                                  std::size_t kept_samples) {
    std::vector<double> x;
    std::vector<double> y;
    for (const auto& p : index.problems()) {
        const RunGroup* ref = index.find(p, reference);
        const RunGroup* other = index.find(p, algorithm);
        if (ref == nullptr || other == nullptr)
            continue;
        if (!ref->optimum_known() || !other->optimum_known())
            return std::nullopt; // raw f of different problems are not one scale
        x.push_back(median_value(*ref));
        y.push_back(median_value(*other));
    }
    if (x.size() < 2)
        return std::nullopt;
    BayesianComparison c;
    c.problem = "all problems (" + std::to_string(x.size()) + ")";
    c.algorithm = algorithm;
    c.across_problems = true;
    c.rope = rope.log10_gap;
    c.result = bayesian_signed_rank(paired_differences(x, y), test_options(c.problem, algorithm, reference,
                                                                           rope.log10_gap, kept_samples));
    return c;
}

std::string rope_text(const BayesianComparison& c) {
    return c.rope ? csv_number(*c.rope) : std::string();
}

} // namespace

std::vector<BayesianComparison> bayesian_comparisons(const StudyIndex& index, const std::string& reference,
                                                     const BayesianRope& rope, std::size_t kept_samples) {
    // The tests, listed first and run in parallel: each has its own seed and slot, so the result
    // does not depend on the thread count (a study of 24 problems x 8 algorithms has 168 tests).
    struct Job {
        std::string problem; // empty: across problems
        std::string algorithm;
    };
    std::vector<Job> jobs;
    for (const auto& p : index.problems()) {
        if (index.find(p, reference) == nullptr)
            continue;
        for (const auto& a : index.algorithms_on(p))
            if (a != reference)
                jobs.push_back({p, a});
    }
    for (const auto& a : index.algorithms())
        if (a != reference)
            jobs.push_back({"", a});
    std::vector<std::optional<BayesianComparison>> slots(jobs.size());
    tbb::parallel_for(std::size_t{0}, jobs.size(), [&](std::size_t i) {
        const Job& job = jobs[i];
        slots[i] = job.problem.empty()
                       ? across_problems(index, job.algorithm, reference, rope, kept_samples)
                       : on_problem(index, job.problem, job.algorithm, reference, rope, kept_samples);
    });
    std::vector<BayesianComparison> out;
    for (auto& slot : slots)
        if (slot)
            out.push_back(std::move(*slot));
    return out;
}

std::string bayesian_csv(const StudyIndex& index, const std::string& reference,
                         const std::vector<BayesianComparison>& comparisons) {
    std::string out = "problem,algorithm,reference,across_problems,scale,rope,pairs,p_reference_better,"
                      "p_equivalent,p_algorithm_better,theta_reference_better,theta_equivalent,"
                      "theta_algorithm_better\n";
    for (const auto& c : comparisons) {
        if (!c.paired)
            continue;
        const BayesianSignedRank& r = c.result;
        out += csv_field(c.problem) + ',' + csv_field(index.label(c.algorithm)) + ',' +
               csv_field(index.label(reference)) + ',' + (c.across_problems ? "1" : "0") + ',' +
               (c.log10_gap ? "log10_gap" : "f") + ',' + rope_text(c) + ',' +
               csv_number(static_cast<std::int64_t>(r.pairs)) + ',' + csv_number(r.left) + ',' +
               csv_number(r.rope) + ',' + csv_number(r.right) + ',' + csv_number(r.mean_theta[0]) + ',' +
               csv_number(r.mean_theta[1]) + ',' + csv_number(r.mean_theta[2]) + '\n';
    }
    return out;
}

std::string bayesian_samples_csv(const StudyIndex& index,
                                 const std::vector<BayesianComparison>& comparisons) {
    const bool any_across = std::any_of(comparisons.begin(), comparisons.end(),
                                        [](const BayesianComparison& c) { return c.across_problems; });
    std::string out =
        "problem,algorithm,sample,theta_reference_better,theta_equivalent,theta_algorithm_better\n";
    for (const auto& c : comparisons) {
        if (!c.paired || c.across_problems != any_across)
            continue;
        for (std::size_t s = 0; s < c.result.thetas.size(); ++s) {
            const auto& t = c.result.thetas[s];
            out += csv_field(c.problem) + ',' + csv_field(index.label(c.algorithm)) + ',' +
                   csv_number(static_cast<std::int64_t>(s)) + ',' + csv_number(t[0]) + ',' +
                   csv_number(t[1]) + ',' + csv_number(t[2]) + '\n';
        }
    }
    return out;
}

} // namespace mhb
