#include "results/analysis/sample_size.hpp"

#include <algorithm>
#include <boost/math/distributions/non_central_t.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "problems/core/parameters.hpp" // format_real

namespace mhb {

namespace {

// The ARE of the Wilcoxon signed-rank test to the t-test that CAISEr divides by.
constexpr double wilcoxon_efficiency = 0.86;
// Beyond this many problems a plan is no plan: a d this small is not worth detecting.
constexpr std::int64_t most_instances = 10000000;

std::vector<double> holm_levels(std::int64_t comparisons, double alpha) {
    std::vector<double> levels;
    for (std::int64_t i = 1; i <= comparisons; ++i)
        levels.push_back(alpha / static_cast<double>(comparisons - i + 1));
    return levels;
}

} // namespace

double paired_t_power(std::int64_t n, double d, double alpha) {
    if (n < 2)
        return 0.0;
    const double nu = static_cast<double>(n - 1);
    const double critical =
        boost::math::quantile(boost::math::complement(boost::math::students_t(nu), alpha / 2));
    const boost::math::non_central_t shifted(nu, std::sqrt(static_cast<double>(n)) * d);
    return boost::math::cdf(boost::math::complement(shifted, critical));
}

InstancePlan plan_instances(std::int64_t comparisons, double d, double power, double alpha,
                            PowerTarget target, PlannedTest test) {
    if (!(d > 0) || !std::isfinite(d))
        throw std::invalid_argument("effect = " + format_real(d) + " is outside (0, inf)");
    if (!(alpha > 0 && alpha < 1))
        throw std::invalid_argument("alpha = " + format_real(alpha) + " is outside (0, 1)");
    if (!(power > 0 && power < 1))
        throw std::invalid_argument("power = " + format_real(power) + " is outside (0, 1)");
    if (comparisons < 1)
        throw std::invalid_argument("comparisons = " + std::to_string(comparisons) + " is outside [1, inf)");
    InstancePlan plan;
    plan.levels = holm_levels(comparisons, alpha);
    const auto reached = [&](std::int64_t n) {
        plan.powers.clear();
        for (const double level : plan.levels)
            plan.powers.push_back(paired_t_power(n, d, level));
        plan.mean_power = std::accumulate(plan.powers.begin(), plan.powers.end(), 0.0) /
                          static_cast<double>(plan.powers.size());
        return (target == PowerTarget::mean ? plan.mean_power : plan.powers.front()) >= power;
    };
    // Power grows with n: double to an upper bound, then bisect to the smallest n that reaches it.
    std::int64_t low = 1;
    std::int64_t high = 2;
    while (!reached(high)) {
        low = high;
        high *= 2;
        if (high > most_instances)
            throw std::invalid_argument("effect = " + format_real(d) + " needs more than " +
                                        std::to_string(most_instances) + " problems");
    }
    while (high - low > 1) {
        const std::int64_t middle = low + (high - low) / 2;
        (reached(middle) ? high : low) = middle;
    }
    reached(high);
    plan.t_test_instances = high;
    plan.instances =
        test == PlannedTest::t_test
            ? high
            : static_cast<std::int64_t>(std::ceil(static_cast<double>(high) / wilcoxon_efficiency));
    return plan;
}

std::int64_t runs_for_precision(double sd, double precision) {
    if (!(precision > 0))
        throw std::invalid_argument("precision must be positive");
    if (!std::isfinite(sd))
        throw std::invalid_argument("the standard deviation is not finite");
    const double ratio = sd / precision;
    return std::max<std::int64_t>(2, static_cast<std::int64_t>(std::ceil(ratio * ratio - 1e-9)));
}

} // namespace mhb
