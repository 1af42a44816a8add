#include "results/analysis/critical_difference.hpp"

#include <array>
#include <cmath>

#include "results/analysis/hypothesis_tests.hpp"
#include "results/analysis/problem_medians.hpp"
#include "results/store/csv.hpp" // CSV as the store writes it, for every room

namespace mhb {

namespace {

// Demsar (2006), Table 5(a) and 5(b): critical values of the two-tailed Nemenyi test, k = 2..10.
constexpr std::array<double, 9> q_005 = {1.960, 2.343, 2.569, 2.728, 2.850, 2.949, 3.031, 3.102, 3.164};
constexpr std::array<double, 9> q_010 = {1.645, 2.052, 2.291, 2.459, 2.589, 2.693, 2.780, 2.855, 2.920};

} // namespace

std::optional<double> nemenyi_critical_difference(std::size_t algorithms, std::size_t problems,
                                                  double alpha) {
    if (algorithms < 2 || algorithms > 10 || problems == 0)
        return std::nullopt;
    const std::array<double, 9>* table = nullptr;
    if (alpha == 0.05)
        table = &q_005;
    else if (alpha == 0.10)
        table = &q_010;
    else
        return std::nullopt;
    const double k = static_cast<double>(algorithms);
    return (*table)[algorithms - 2] * std::sqrt(k * (k + 1.0) / (6.0 * static_cast<double>(problems)));
}

std::optional<std::string> critical_difference_data(const StudyIndex& index, double alpha) {
    const auto blocks = per_problem_medians(index);
    if (!blocks)
        return std::nullopt;
    const auto cd = nemenyi_critical_difference(index.algorithms().size(), blocks->first.size(), alpha);
    if (!cd)
        return std::nullopt;
    const FriedmanResult friedman = friedman_test(blocks->second);
    std::string out = "algorithm,label,average_rank,cd,alpha,problems\n";
    for (std::size_t j = 0; j < index.algorithms().size(); ++j)
        out += csv_field(index.algorithms()[j]) + ',' + csv_field(index.label(index.algorithms()[j])) + ',' +
               csv_number(friedman.average_ranks[j]) + ',' + csv_number(*cd) + ',' + csv_number(alpha) + ',' +
               std::to_string(blocks->first.size()) + '\n';
    return out;
}

} // namespace mhb
