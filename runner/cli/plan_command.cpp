// `mhbench plan`: how many problems and runs a comparison needs, before any run (results/analysis/
// sample_size.hpp): the problems to detect an effect of size d with a given power, and the runs per
// problem for a given precision, from a standard deviation given or measured in a pilot study.
#include <algorithm>
#include <boost/program_options.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "results/analysis/run_precision.hpp"
#include "results/analysis/sample_size.hpp"
#include "results/analysis/statistics.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_index.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"

namespace mhb::cli {

namespace po = boost::program_options;

namespace {

struct PlanCommandLine {
    double effect = 0;
    double power = 0.8;
    double alpha = 0.05;
    std::string algorithms = "2";
    std::string test = "wilcoxon";
    std::string power_target = "mean";
    double precision = 0;
    double sd = 0;
    std::string pilot;
};

po::options_description plan_options(PlanCommandLine& given) {
    po::options_description visible(
        "Usage: mhbench plan --effect D [options]          problems needed\n"
        "       mhbench plan --precision E --sd S           runs per problem\n"
        "       mhbench plan --precision E --pilot DIR      runs per problem and algorithm, from a pilot "
        "study\n\n"
        "Answers before a study how large it must be (Campelo & Takahashi, J. Heuristics 25, 2019; Campelo "
        "&\n"
        "Wanner; the R package CAISEr's calc_instances and calc_nreps):\n"
        "  - problems: the smallest number at which a two-sided paired t-test of the per-problem mean\n"
        "    differences to the reference detects a standardised effect D (mean difference / its standard\n"
        "    deviation across problems; 0.2 small, 0.5 medium, 0.8 large) with the power asked, each of the\n"
        "    comparisons with the reference at its Holm level; power from the noncentral t distribution,\n"
        "    as R's power.t.test; a Wilcoxon signed-rank test needs that number / 0.86 (its asymptotic\n"
        "    relative efficiency);\n"
        "  - runs per problem: ceil((S / E)^2), after which the standard error of a mean difference with\n"
        "    standard deviation S is at most E; with --pilot, S is measured per problem and algorithm as\n"
        "    the standard deviation of the paired differences of log10(f - f*) (f where f* is unknown) to\n"
        "    the reference, the scale `run --runs auto --precision E` stops on.\n\nOptions");
    visible.add_options()("help,h", "this text")("effect", po::value(&given.effect),
                                                 "standardised effect size D to detect, > 0")(
        "power", po::value(&given.power)->default_value(0.8, "0.8"),
        "power wanted, in (0, 1)")("alpha", po::value(&given.alpha)->default_value(0.05, "0.05"),
                                   "family-wise significance level, in (0, 1)")(
        "algorithms", po::value(&given.algorithms)->default_value("2"),
        "algorithms in the study: each but the reference is one comparison")(
        "test", po::value(&given.test)->default_value("wilcoxon"),
        "wilcoxon (the report's paired test across problems) or t")(
        "power-target", po::value(&given.power_target)->default_value("mean"),
        "mean: the comparisons' mean power reaches --power (CAISEr's default); worst-case: every one does "
        "(Bonferroni)")("precision", po::value(&given.precision), "standard error wanted, > 0")(
        "sd", po::value(&given.sd), "standard deviation of a paired difference, for --precision")(
        "pilot", po::value(&given.pilot), "a finished study to measure the standard deviations in");
    return visible;
}

void print_instances(const PlanCommandLine& given) {
    const std::int64_t algorithms = integer_argument(given.algorithms, "algorithms", 2, 100000);
    if (given.test != "wilcoxon" && given.test != "t")
        throw std::invalid_argument("--test = " + value_excerpt(given.test) + " is not one of {wilcoxon, t}");
    if (given.power_target != "mean" && given.power_target != "worst-case")
        throw std::invalid_argument("--power-target = " + value_excerpt(given.power_target) +
                                    " is not one of {mean, worst-case}");
    const bool wilcoxon = given.test == "wilcoxon";
    const InstancePlan plan =
        plan_instances(algorithms - 1, given.effect, given.power, given.alpha,
                       given.power_target == "mean" ? PowerTarget::mean : PowerTarget::worst_case,
                       wilcoxon ? PlannedTest::wilcoxon : PlannedTest::t_test);
    char line[400];
    std::snprintf(line, sizeof line,
                  "problems: %lld, to detect a standardised effect d = %g with %s power %g in %s%lld "
                  "comparison%s with the reference (Holm, family-wise alpha = %g)\n",
                  static_cast<long long>(plan.instances), given.effect,
                  given.power_target == "mean" ? "mean" : "worst-case", given.power,
                  algorithms == 2 ? "" : "each of ", static_cast<long long>(algorithms - 1),
                  algorithms == 2 ? "" : "s", given.alpha);
    std::cout << line;
    std::snprintf(line, sizeof line, "  paired t-test: %lld problems, power %.3f",
                  static_cast<long long>(plan.t_test_instances), plan.powers.front());
    std::cout << line;
    if (plan.powers.size() > 1) {
        std::snprintf(line, sizeof line,
                      " (most significant comparison, alpha %.3g) to %.3f (alpha %.3g), mean %.3f",
                      plan.levels.front(), plan.powers.back(), plan.levels.back(), plan.mean_power);
        std::cout << line;
    }
    std::cout << '\n';
    if (wilcoxon)
        std::cout << "  Wilcoxon signed-rank: " << plan.t_test_instances << " / 0.86 = " << plan.instances
                  << " problems (its asymptotic relative efficiency to the t-test)\n";
    std::cout << "method: Campelo & Takahashi, J. Heuristics 25 (2019) 305-338, as CAISEr's calc_instances\n";
}

// Per problem and algorithm of a pilot study: the paired differences' standard deviation and the runs
// it asks for.
void print_pilot_runs(const std::string& dir, double precision) {
    const StudyData data = load_study(dir);
    for (const std::string& budget : study_budgets(data)) {
        const StudyIndex index(data, budget);
        const std::string& reference = index.algorithms()[default_reference_index(index.algorithms())];
        std::cout << "budget " << budget << ", against " << index.label(reference) << " (standard error "
                  << format_real(precision) << "):\n";
        for (const std::string& problem : index.problems()) {
            const RunGroup* ref = index.find(problem, reference);
            for (const std::string& algorithm : index.algorithms()) {
                const RunGroup* group = index.find(problem, algorithm);
                if (group == nullptr || ref == nullptr ||
                    (algorithm == reference && index.algorithms().size() > 1))
                    continue;
                // The rule's own scale (compared_value); a study of one algorithm: its values alone.
                const PairedValues pairs = paired_values(*group, *ref, compared_value);
                const std::vector<double> differences =
                    algorithm == reference ? pairs.x : paired_differences(pairs.x, pairs.y);
                const double sd = standard_deviation(differences);
                char line[300];
                std::snprintf(line, sizeof line, "  %-28s %-16s %3zu pilot runs, sd %-9.3g -> %s\n",
                              problem.c_str(), index.label(algorithm).c_str(), differences.size(), sd,
                              std::isfinite(sd) && differences.size() >= 2
                                  ? (std::to_string(runs_for_precision(sd, precision)) + " runs").c_str()
                                  : "unknown (fewer than 2 runs, or an infinite value)");
                std::cout << line;
            }
        }
    }
}

} // namespace

int run_plan_command(const std::vector<std::string>& args) {
    PlanCommandLine given;
    const po::options_description options = plan_options(given);
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { std::cout << options << '\n'; }))
        return exit_ok;
    const bool instances = vm.count("effect") != 0;
    const bool runs = vm.count("precision") != 0;
    if (!instances && !runs)
        throw std::invalid_argument(
            "give --effect D (problems needed) or --precision E with --sd S or --pilot DIR "
            "(runs per problem); see --help");
    if (instances)
        print_instances(given);
    if (!runs)
        return exit_ok;
    if (!(given.precision > 0) || !std::isfinite(given.precision))
        throw std::invalid_argument("--precision = " + format_real(given.precision) + " is outside (0, inf)");
    if ((vm.count("sd") != 0) == (vm.count("pilot") != 0))
        throw std::invalid_argument("--precision needs --sd S or --pilot DIR (one of them)");
    if (vm.count("sd") != 0) {
        if (!(given.sd >= 0) || !std::isfinite(given.sd))
            throw std::invalid_argument("--sd = " + format_real(given.sd) + " is outside [0, inf)");
        std::cout << "runs per problem: " << runs_for_precision(given.sd, given.precision)
                  << ", for a standard error of " << format_real(given.precision)
                  << " at a standard deviation of " << format_real(given.sd)
                  << " (ceil((sd / precision)^2))\n";
        return exit_ok;
    }
    print_pilot_runs(given.pilot, given.precision);
    return exit_ok;
}

} // namespace mhb::cli
