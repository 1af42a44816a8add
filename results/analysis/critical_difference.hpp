// The critical difference of the Nemenyi test (Demsar 2006, "Statistical comparisons of classifiers
// over multiple data sets", JMLR 7:1-30): two algorithms' average Friedman ranks over N problems
// differ significantly when they differ by more than CD = q_alpha sqrt(k (k + 1) / (6 N)). The
// q_alpha (studentized range / sqrt 2) come from Demsar's Table 5, for alpha 0.05 and 0.10 and
// k = 2..10 algorithms; Boost.Math has no studentized range distribution to compute other cases.
#pragma once

#include <optional>
#include <string>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

// Empty when alpha is not 0.05 or 0.10 or k is outside 2..10.
std::optional<double> nemenyi_critical_difference(std::size_t algorithms, std::size_t problems, double alpha);

// The data of a critical-difference diagram as CSV (algorithm,label,average_rank,cd,alpha,problems), or
// empty when the study has fewer than two complete problems or no tabulated q_alpha applies.
std::optional<std::string> critical_difference_data(const StudyIndex& index, double alpha);

} // namespace mhb
