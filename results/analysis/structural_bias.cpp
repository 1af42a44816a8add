#include "results/analysis/structural_bias.hpp"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "results/analysis/hypothesis_tests.hpp" // holm_adjust
#include "results/store/csv.hpp"

namespace mhb {
namespace {

// Two-sided one-sample t-test of `values` against `mu`.
double one_sample_t_p(const std::vector<double>& values, double mu) {
    const double n = static_cast<double>(values.size());
    double mean = 0.0;
    for (double v : values)
        mean += v / n;
    double squares = 0.0;
    for (double v : values)
        squares += (v - mean) * (v - mean);
    const double sd = std::sqrt(squares / (n - 1.0));
    if (!(sd > 0.0))
        return mean == mu ? 1.0 : 0.0;
    const double t = (mean - mu) / (sd / std::sqrt(n));
    const boost::math::students_t distribution(n - 1.0);
    return std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(distribution, std::fabs(t))));
}

// P(X >= k) for X ~ Binomial(n, p): the regularised incomplete beta I_p(k, n - k + 1).
double binomial_upper_p(std::size_t k, std::size_t n, double p) {
    if (k == 0)
        return 1.0;
    return boost::math::ibeta(static_cast<double>(k), static_cast<double>(n - k + 1), p);
}

std::string classify(const BiasAudit& a, double alpha) {
    if (a.ks_rejected == 0 && a.ad_rejected == 0)
        return "no bias detected";
    const bool located = a.centre_distance_p < alpha;
    const bool centre = located && a.centre_distance < uniform_centre_distance;
    const bool bounds = a.near_bound_p < alpha || (located && a.centre_distance > uniform_centre_distance);
    if (centre && !bounds)
        return "centre";
    if (bounds && !centre)
        return "bounds";
    return "other";
}

void test_dimensions(const std::vector<std::vector<double>>& points, double alpha, BiasAudit& audit) {
    const std::size_t d = points.front().size();
    std::vector<double> ks_p;
    std::vector<double> ad_p;
    for (std::size_t j = 0; j < d; ++j) {
        std::vector<double> column;
        for (const auto& x : points)
            column.push_back(x[j]);
        DimensionUniformity u{kolmogorov_smirnov_uniform(column), anderson_darling_uniform(column)};
        ks_p.push_back(u.ks.p_value);
        ad_p.push_back(u.ad.p_value);
        audit.dimensions.push_back(u);
    }
    const std::vector<double> ks_holm = holm_adjust(ks_p);
    const std::vector<double> ad_holm = holm_adjust(ad_p);
    for (std::size_t j = 0; j < d; ++j) {
        audit.dimensions[j].ks_holm_p = ks_holm[j];
        audit.dimensions[j].ad_holm_p = ad_holm[j];
        audit.ks_rejected += ks_holm[j] < alpha ? 1U : 0U;
        audit.ad_rejected += ad_holm[j] < alpha ? 1U : 0U;
        audit.smallest_holm_p = std::min({audit.smallest_holm_p, ks_holm[j], ad_holm[j]});
    }
}

void locate_points(const std::vector<std::vector<double>>& points, BiasAudit& audit) {
    std::vector<double> run_means;
    std::size_t near_lower = 0;
    std::size_t near_upper = 0;
    std::size_t coordinates = 0;
    for (const auto& x : points) {
        double sum = 0.0;
        for (double v : x) {
            sum += std::fabs(v - 0.5);
            near_lower += v <= bias_bound_width ? 1U : 0U;
            near_upper += v >= 1.0 - bias_bound_width ? 1U : 0U;
        }
        run_means.push_back(sum / static_cast<double>(x.size()));
        coordinates += x.size();
    }
    double mean = 0.0;
    for (double m : run_means)
        mean += m / static_cast<double>(run_means.size());
    audit.centre_distance = mean;
    audit.centre_distance_p = one_sample_t_p(run_means, uniform_centre_distance);
    const std::size_t near_bound = near_lower + near_upper;
    audit.near_bound_share = static_cast<double>(near_bound) / static_cast<double>(coordinates);
    audit.near_lower_share = static_cast<double>(near_lower) / static_cast<double>(coordinates);
    audit.near_upper_share = static_cast<double>(near_upper) / static_cast<double>(coordinates);
    audit.near_bound_p = binomial_upper_p(near_bound, coordinates, uniform_bound_share);
}

} // namespace

bool is_bias_problem(const std::string& problem_spec) {
    return split_spec_text(problem_spec).name == "f0";
}

BiasAudit audit_final_points(const std::vector<std::vector<double>>& points, double alpha) {
    if (points.size() < 2)
        throw std::invalid_argument("structural-bias audit: needs the final points of two runs or more");
    std::vector<std::vector<double>> inside = points;
    for (auto& x : inside) {
        if (x.empty() || x.size() != points.front().size())
            throw std::invalid_argument("structural-bias audit: the final points differ in dimension");
        for (double& v : x)
            v = std::clamp(v, 0.0, 1.0);
    }
    BiasAudit audit;
    audit.runs = points.size();
    test_dimensions(inside, alpha, audit);
    locate_points(inside, audit);
    audit.verdict = classify(audit, alpha);
    return audit;
}

std::vector<BiasAudit> structural_bias_audits(const StudyIndex& index, double alpha) {
    std::vector<BiasAudit> audits;
    for (const auto& problem : index.problems()) {
        if (!is_bias_problem(problem))
            continue;
        for (const auto& algorithm : index.algorithms_on(problem)) {
            std::vector<std::vector<double>> points;
            for (const RunRecord* r : index.find(problem, algorithm)->runs)
                if (!r->best_x.empty())
                    points.push_back(r->best_x);
            if (points.size() < 2)
                continue;
            BiasAudit audit = audit_final_points(points, alpha);
            audit.problem = problem;
            audit.algorithm = algorithm;
            audits.push_back(std::move(audit));
        }
    }
    return audits;
}

std::optional<std::string> uniformity_tests_csv(const StudyIndex& index, double alpha) {
    const std::vector<BiasAudit> audits = structural_bias_audits(index, alpha);
    if (audits.empty())
        return std::nullopt;
    std::string csv =
        "problem,algorithm,runs,dimension,ks_statistic,ks_p,ks_holm_p,ad_statistic,ad_p,ad_holm_p\n";
    char numbers[200];
    for (const BiasAudit& a : audits)
        for (std::size_t j = 0; j < a.dimensions.size(); ++j) {
            const DimensionUniformity& d = a.dimensions[j];
            std::snprintf(numbers, sizeof numbers, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", d.ks.statistic,
                          d.ks.p_value, d.ks_holm_p, d.ad.statistic, d.ad.p_value, d.ad_holm_p);
            csv += csv_field(a.problem) + ',' + csv_field(index.label(a.algorithm)) + ',' +
                   std::to_string(a.runs) + ',' + std::to_string(j + 1) + ',' + numbers + '\n';
        }
    return csv;
}

std::optional<std::string> final_points_csv(const StudyIndex& index) {
    const auto& problems = index.problems();
    if (std::none_of(problems.begin(), problems.end(), is_bias_problem))
        return std::nullopt;
    std::string csv = "problem,algorithm,run,dimension,x\n";
    char number[40];
    for (const auto& problem : index.problems()) {
        if (!is_bias_problem(problem))
            continue;
        for (const auto& algorithm : index.algorithms_on(problem))
            for (const RunRecord* r : index.find(problem, algorithm)->runs)
                for (std::size_t j = 0; j < r->best_x.size(); ++j) {
                    std::snprintf(number, sizeof number, "%.17g", r->best_x[j]);
                    csv += csv_field(problem) + ',' + csv_field(index.label(algorithm)) + ',' +
                           std::to_string(r->run_index) + ',' + std::to_string(j + 1) + ',' + number + '\n';
                }
    }
    return csv;
}

} // namespace mhb
