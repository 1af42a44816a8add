// Goodness-of-fit tests of a sample against the uniform distribution on [0, 1], for the
// structural-bias audit (structural_bias.hpp), where a sample is one coordinate of the final best
// points of an optimiser's runs on f0:
//  - one-sample Kolmogorov-Smirnov, two-sided, D = sup |F_n - F|, with the exact p-value as
//    scipy.stats.kstest(method='exact') gives it (scipy's kstwo, after Simard and L'Ecuyer 2011,
//    "Computing the two-sided Kolmogorov-Smirnov distribution", J. Stat. Softw. 39(11)): Marsaglia,
//    Tsang and Wang's matrix (2003, J. Stat. Softw. 8(18)) where n d^2 <= 4, and twice the exact
//    one-sided Smirnov tail (Birnbaum and Tingey 1951) beyond, where the two tails no longer meet;
//  - Anderson-Darling A^2 against U(0, 1), with Marsaglia and Marsaglia's p-value (2004,
//    "Evaluating the Anderson-Darling distribution", J. Stat. Softw. 9(2): their ADinf and the
//    finite-n correction errfix, accurate to about 5 digits), which weighs the tails, where
//    points pulled to the bounds of the box land, more than KS does.
// A value exactly at 0 or 1 makes A^2 infinite (p = 0): U(0, 1) puts no mass there.
#pragma once

#include <cstddef>
#include <vector>

namespace mhb {

struct UniformityTest {
    double statistic = 0; // KS: D; AD: A^2
    double p_value = 1;
};

// Throws std::invalid_argument for an empty sample or a value outside [0, 1] (or NaN).
UniformityTest kolmogorov_smirnov_uniform(std::vector<double> sample);
UniformityTest anderson_darling_uniform(std::vector<double> sample);

// P(D_n >= d) for n uniform values (scipy.stats.kstwo.sf(d, n)).
double kolmogorov_smirnov_p_value(std::size_t n, double d);
// P(A_n^2 >= a) for n uniform values (1 - Marsaglia's AD(n, a)).
double anderson_darling_p_value(std::size_t n, double a);

} // namespace mhb
