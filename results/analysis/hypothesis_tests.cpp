#include "results/analysis/hypothesis_tests.hpp"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace mhb {

namespace {

double two_sided_normal_p(double z) {
    const boost::math::normal standard;
    return std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(standard, std::fabs(z))));
}

// Sizes of the groups of tied values (only groups of two or more matter).
std::vector<double> tie_sizes(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    std::vector<double> sizes;
    for (std::size_t i = 0; i < values.size();) {
        std::size_t j = i;
        while (j < values.size() && values[j] == values[i])
            ++j;
        if (j - i > 1)
            sizes.push_back(static_cast<double>(j - i));
        i = j;
    }
    return sizes;
}

double tie_term(const std::vector<double>& sizes) {
    double sum = 0.0;
    for (double t : sizes)
        sum += t * t * t - t;
    return sum;
}

// Two-sided p of an integer statistic s under a symmetric discrete null given by counts[0..max].
double exact_two_sided(const std::vector<double>& counts, std::size_t s) {
    const double total = std::accumulate(counts.begin(), counts.end(), 0.0);
    double lower = 0.0;
    for (std::size_t u = 0; u <= s && u < counts.size(); ++u)
        lower += counts[u];
    double upper = 0.0;
    for (std::size_t u = s; u < counts.size(); ++u)
        upper += counts[u];
    return std::min(1.0, 2.0 * std::min(lower, upper) / total);
}

// Null distribution of Mann-Whitney U for sizes m, n, by the counting recurrence
// N(i, j, u) = N(i - 1, j, u - j) + N(i, j - 1, u) (the largest of the i + j values belongs to x,
// adding j to U, or to y). Only additions, so the counts stay exact to double rounding even in the
// far tails (a product formula with subtractions would cancel there).
std::vector<double> mann_whitney_counts(std::size_t m, std::size_t n) {
    // by_i[i] = distribution of U for sizes (i, j), for the current j; starts at j = 0.
    std::vector<std::vector<double>> by_i(m + 1, std::vector<double>(m * n + 1, 0.0));
    for (auto& d : by_i)
        d[0] = 1.0; // (i, 0): U = 0 only
    for (std::size_t j = 1; j <= n; ++j)
        for (std::size_t i = 1; i <= m; ++i) // by_i[i - 1] already holds (i - 1, j)
            for (std::size_t u = i * j + 1; u-- > j;)
                by_i[i][u] += by_i[i - 1][u - j];
    return by_i[m];
}

// Null distribution of the signed-rank statistic for n pairs: subsets of {1..n} by their sum.
std::vector<double> signed_rank_counts(std::size_t n) {
    std::vector<double> c(n * (n + 1) / 2 + 1, 0.0);
    c[0] = 1.0;
    for (std::size_t k = 1; k <= n; ++k)
        for (std::size_t s = c.size(); s-- > k;)
            c[s] += c[s - k];
    return c;
}

} // namespace

std::vector<double> average_ranks(const std::vector<double>& values) {
    std::vector<std::size_t> order(values.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    std::vector<double> ranks(values.size());
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i;
        while (j < order.size() && values[order[j]] == values[order[i]])
            ++j;
        const double rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
        for (std::size_t k = i; k < j; ++k)
            ranks[order[k]] = rank;
        i = j;
    }
    return ranks;
}

TestResult rank_sum_test(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.empty() || y.empty())
        throw std::invalid_argument("Wilcoxon rank-sum test needs two non-empty samples");
    std::vector<double> pooled = x;
    pooled.insert(pooled.end(), y.begin(), y.end());
    const std::vector<double> ranks = average_ranks(pooled);
    const double m = static_cast<double>(x.size());
    const double n = static_cast<double>(y.size());
    double rank_sum_x = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i)
        rank_sum_x += ranks[i];
    TestResult r;
    r.statistic = rank_sum_x - m * (m + 1.0) / 2.0;
    const std::vector<double> ties = tie_sizes(pooled);
    if (x.size() < exact_test_limit && y.size() < exact_test_limit && ties.empty()) {
        r.name = "Wilcoxon rank-sum (Mann-Whitney U), exact";
        r.exact = true;
        r.p_value = exact_two_sided(mann_whitney_counts(x.size(), y.size()),
                                    static_cast<std::size_t>(std::lround(r.statistic)));
        return r;
    }
    r.name = "Wilcoxon rank-sum (Mann-Whitney U), normal approx. with tie and continuity correction";
    const double centred = r.statistic - m * n / 2.0;
    const double sigma =
        std::sqrt(m * n / 12.0 * ((m + n + 1.0) - tie_term(ties) / ((m + n) * (m + n - 1.0))));
    if (sigma == 0.0) { // every value equal: no evidence either way
        r.p_value = 1.0;
        return r;
    }
    const double correction = centred > 0 ? 0.5 : (centred < 0 ? -0.5 : 0.0);
    r.z = (centred - correction) / sigma;
    r.p_value = two_sided_normal_p(r.z);
    return r;
}

TestResult signed_rank_test(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size())
        throw std::invalid_argument("Wilcoxon signed-rank test needs pairs: samples of equal length");
    std::vector<double> differences;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i] != y[i]) // equal values (two +inf included, whose difference would be NaN) are a tie
            differences.push_back(x[i] - y[i]);
    TestResult r;
    if (differences.empty()) {
        r.name = "Wilcoxon signed-rank";
        return r;
    }
    std::vector<double> magnitudes(differences.size());
    for (std::size_t i = 0; i < differences.size(); ++i)
        magnitudes[i] = std::fabs(differences[i]);
    const std::vector<double> ranks = average_ranks(magnitudes);
    for (std::size_t i = 0; i < differences.size(); ++i)
        if (differences[i] > 0)
            r.statistic += ranks[i];
    const std::vector<double> ties = tie_sizes(magnitudes);
    const bool had_zeros = differences.size() != x.size();
    if (differences.size() < exact_test_limit && ties.empty() && !had_zeros) {
        r.name = "Wilcoxon signed-rank, exact";
        r.exact = true;
        r.p_value = exact_two_sided(signed_rank_counts(differences.size()),
                                    static_cast<std::size_t>(std::lround(r.statistic)));
        return r;
    }
    r.name = "Wilcoxon signed-rank, normal approx. with tie and continuity correction";
    const double n = static_cast<double>(differences.size());
    const double centred = r.statistic - n * (n + 1.0) / 4.0;
    const double sigma = std::sqrt(n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - tie_term(ties) / 48.0);
    const double correction = centred > 0 ? 0.5 : (centred < 0 ? -0.5 : 0.0);
    r.z = sigma > 0 ? (centred - correction) / sigma : 0.0;
    r.p_value = sigma > 0 ? two_sided_normal_p(r.z) : 1.0;
    return r;
}

FriedmanResult friedman_test(const std::vector<std::vector<double>>& blocks) {
    if (blocks.size() < 2 || blocks.front().size() < 2)
        throw std::invalid_argument("Friedman test needs at least two blocks and two treatments");
    const std::size_t k = blocks.front().size();
    FriedmanResult r;
    r.average_ranks.assign(k, 0.0);
    double ties = 0.0;
    for (const auto& row : blocks) {
        if (row.size() != k)
            throw std::invalid_argument("Friedman test needs every block to have the same treatments");
        const std::vector<double> ranks = average_ranks(row);
        for (std::size_t j = 0; j < k; ++j)
            r.average_ranks[j] += ranks[j];
        ties += tie_term(tie_sizes(row));
    }
    const double n = static_cast<double>(blocks.size());
    const double kd = static_cast<double>(k);
    double spread = 0.0;
    for (double& rank_sum : r.average_ranks) {
        spread += (rank_sum - n * (kd + 1.0) / 2.0) * (rank_sum - n * (kd + 1.0) / 2.0);
        rank_sum /= n;
    }
    const double denominator = n * kd * (kd + 1.0) - ties / (kd - 1.0);
    r.degrees_of_freedom = kd - 1.0;
    if (denominator <= 0.0) // every block all ties
        return r;
    r.chi_square = 12.0 * spread / denominator;
    const boost::math::chi_squared chi(r.degrees_of_freedom);
    r.p_value = boost::math::cdf(boost::math::complement(chi, r.chi_square));
    return r;
}

std::vector<double> friedman_posthoc_p_values(const std::vector<double>& average_ranks, std::size_t blocks,
                                              std::size_t control) {
    if (control >= average_ranks.size() || blocks == 0)
        throw std::invalid_argument("Friedman post-hoc: control index out of range or no blocks");
    const double k = static_cast<double>(average_ranks.size());
    const double se = std::sqrt(k * (k + 1.0) / (6.0 * static_cast<double>(blocks)));
    std::vector<double> p(average_ranks.size(), 1.0);
    for (std::size_t j = 0; j < average_ranks.size(); ++j)
        if (j != control)
            p[j] = two_sided_normal_p((average_ranks[j] - average_ranks[control]) / se);
    return p;
}

std::vector<double> holm_adjust(const std::vector<double>& p_values) {
    const std::size_t m = p_values.size();
    std::vector<std::size_t> order(m);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return p_values[a] < p_values[b]; });
    std::vector<double> adjusted(m);
    double running = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
        running = std::max(running, std::min(1.0, static_cast<double>(m - i) * p_values[order[i]]));
        adjusted[order[i]] = running;
    }
    return adjusted;
}

double vargha_delaney_a12(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.empty() || y.empty())
        throw std::invalid_argument("A12 needs two non-empty samples");
    double score = 0.0;
    for (double a : x)
        for (double b : y)
            score += a > b ? 1.0 : (a == b ? 0.5 : 0.0);
    return score / (static_cast<double>(x.size()) * static_cast<double>(y.size()));
}

} // namespace mhb
