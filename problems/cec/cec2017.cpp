// The 30 functions of CEC 2017 in the code's numbering (file index = function number; F2 is kept),
// F* = 100 F, as the official cec17_test_func.cpp defines them (../shared/cec/README.md, section 3-4).
#include "problems/cec/cec_recipe_helpers.hpp"

namespace mhb::cec {

const std::vector<FunctionRecipe>& cec2017_recipes() {
    using namespace recipe;
    using B = Basic;
    static const std::vector<FunctionRecipe> all = [] {
        const std::vector<int> all_dims{2, 10, 20, 30, 50, 100};
        const std::vector<int> hybrid_dims{10, 30, 50, 100}; // no D = 2 or 20 data
        // Hybrids 5-9 are also the components of F29 and F30.
        const HybridRecipe h5{{B::bent_cigar, B::hgbat, B::rastrigin, B::rosenbrock}, {0.2, 0.2, 0.3, 0.3}};
        const HybridRecipe h6{{B::expanded_schaffer_f6, B::hgbat, B::rosenbrock, B::schwefel},
                              {0.2, 0.2, 0.3, 0.3}};
        const HybridRecipe h7{{B::katsuura, B::ackley, B::griewank_rosenbrock, B::schwefel, B::rastrigin},
                              {0.1, 0.2, 0.2, 0.2, 0.3}};
        const HybridRecipe h8{{B::ellipsoid, B::ackley, B::rastrigin, B::hgbat, B::discus},
                              {0.2, 0.2, 0.2, 0.2, 0.2}};
        const HybridRecipe h9{
            {B::bent_cigar, B::rastrigin, B::griewank_rosenbrock, B::weierstrass, B::expanded_schaffer_f6},
            {0.2, 0.2, 0.2, 0.2, 0.2}};
        std::vector<FunctionRecipe> r;
        r.push_back(simple("Shifted and Rotated Bent Cigar", B::bent_cigar, 100, all_dims));
        r.push_back(simple("Shifted and Rotated Sum of Different Power", B::sum_of_different_power, 200,
                           all_dims, true,
                           "dropped from the final CEC 2017 definitions and excluded from the competition; "
                           "kept because the code and data define it"));
        r.push_back(simple("Shifted and Rotated Zakharov", B::zakharov, 300, all_dims));
        r.push_back(simple("Shifted and Rotated Rosenbrock", B::rosenbrock, 400, all_dims));
        r.push_back(simple("Shifted and Rotated Rastrigin", B::rastrigin, 500, all_dims));
        // README Q2: the code computes Schaffer F7 on x - o, unrotated (the report: Expanded Schaffer F6).
        r.push_back(
            simple("Shifted Schaffer F7", B::schaffer_f7, 600, all_dims, false,
                   "the report names Expanded Schaffer F6; the code computes Schaffer F7, unrotated"));
        r.push_back(
            simple("Shifted and Rotated Lunacek bi-Rastrigin", B::lunacek_bi_rastrigin, 700, all_dims));
        // README Q3: the code's rounding step is lost, so this is Rastrigin with F8's own data.
        r.push_back(simple("Shifted and Rotated Non-Continuous Rastrigin", B::rastrigin, 800, all_dims, true,
                           "the code's rounding step has no effect: it is Rastrigin"));
        r.push_back(simple("Shifted and Rotated Levy", B::levy_2017, 900, all_dims, true,
                           "the code's Levy uses w = 1 + (z - 1)/4, so F(o) > 900; the minimum 900 is at "
                           "o + M^-1 1"));
        r.push_back(simple("Shifted and Rotated Schwefel", B::schwefel, 1000, all_dims));
        r.push_back(hybrid("Hybrid Function 1 (N = 3)",
                           {{B::zakharov, B::rosenbrock, B::rastrigin}, {0.2, 0.4, 0.4}}, 1100, hybrid_dims));
        r.push_back(hybrid("Hybrid Function 2 (N = 3)",
                           {{B::ellipsoid, B::schwefel, B::bent_cigar}, {0.3, 0.3, 0.4}}, 1200, hybrid_dims));
        // README Q5: the bi-Rastrigin group is unrotated and takes its signs from o_1 ... o_n.
        r.push_back(hybrid("Hybrid Function 3 (N = 3)",
                           {{B::bent_cigar, B::rosenbrock, B::lunacek_bi_rastrigin}, {0.3, 0.3, 0.4}}, 1300,
                           hybrid_dims));
        // README Q1: the Schaffer F7 group reads the first entries of the permuted vector.
        r.push_back(hybrid("Hybrid Function 4 (N = 4)",
                           {{B::ellipsoid, B::ackley, B::schaffer_f7, B::rastrigin}, {0.2, 0.2, 0.2, 0.4}},
                           1400, hybrid_dims));
        r.push_back(hybrid("Hybrid Function 5 (N = 4)", h5, 1500, hybrid_dims));
        r.push_back(hybrid("Hybrid Function 6 (N = 4)", h6, 1600, hybrid_dims));
        r.push_back(hybrid("Hybrid Function 7 (N = 5)", h7, 1700, hybrid_dims));
        r.push_back(hybrid("Hybrid Function 8 (N = 5)", h8, 1800, hybrid_dims));
        r.push_back(hybrid("Hybrid Function 9 (N = 5)", h9, 1900, hybrid_dims));
        r.push_back(hybrid("Hybrid Function 10 (N = 6)",
                           {{B::hgbat, B::katsuura, B::ackley, B::rastrigin, B::schwefel, B::schaffer_f7},
                            {0.1, 0.1, 0.2, 0.2, 0.2, 0.2}},
                           2000, {10, 20, 30, 50, 100}));
        r.push_back(composition("Composition Function 1 (N = 3)",
                                {part(B::rosenbrock, 1, 1, 10, 0), part(B::ellipsoid, 10000, 1e+10, 20, 100),
                                 part(B::rastrigin, 1, 1, 30, 200)},
                                2100, all_dims));
        r.push_back(composition("Composition Function 2 (N = 3)",
                                {part(B::rastrigin, 1, 1, 10, 0), part(B::griewank, 1000, 100, 20, 100),
                                 part(B::schwefel, 1, 1, 30, 200)},
                                2200, all_dims));
        r.push_back(composition("Composition Function 3 (N = 4)",
                                {part(B::rosenbrock, 1, 1, 10, 0), part(B::ackley, 1000, 100, 20, 100),
                                 part(B::schwefel, 1, 1, 30, 200), part(B::rastrigin, 1, 1, 40, 300)},
                                2300, all_dims));
        r.push_back(composition("Composition Function 4 (N = 4)",
                                {part(B::ackley, 1000, 100, 10, 0), part(B::ellipsoid, 10000, 1e+10, 20, 100),
                                 part(B::griewank, 1000, 100, 30, 200), part(B::rastrigin, 1, 1, 40, 300)},
                                2400, all_dims));
        r.push_back(composition("Composition Function 5 (N = 5)",
                                {part(B::rastrigin, 10000, 1e+3, 10, 0),
                                 part(B::happycat, 1000, 1e+3, 20, 100), part(B::ackley, 1000, 100, 30, 200),
                                 part(B::discus, 10000, 1e+10, 40, 300), part(B::rosenbrock, 1, 1, 50, 400)},
                                2500, all_dims));
        r.push_back(
            composition("Composition Function 6 (N = 5)",
                        {part(B::expanded_schaffer_f6, 10000, 2e+7, 10, 0), part(B::schwefel, 1, 1, 20, 100),
                         part(B::griewank, 1000, 100, 20, 200), part(B::rosenbrock, 1, 1, 30, 300),
                         part(B::rastrigin, 10000, 1e+3, 40, 400)},
                        2600, all_dims));
        r.push_back(composition(
            "Composition Function 7 (N = 6)",
            {part(B::hgbat, 10000, 1000, 10, 0), part(B::rastrigin, 10000, 1e+3, 20, 100),
             part(B::schwefel, 10000, 4e+3, 30, 200), part(B::bent_cigar, 10000, 1e+30, 40, 300),
             part(B::ellipsoid, 10000, 1e+10, 50, 400), part(B::expanded_schaffer_f6, 10000, 2e+7, 60, 500)},
            2700, all_dims));
        r.push_back(composition("Composition Function 8 (N = 6)",
                                {part(B::ackley, 1000, 100, 10, 0), part(B::griewank, 1000, 100, 20, 100),
                                 part(B::discus, 10000, 1e+10, 30, 200), part(B::rosenbrock, 1, 1, 40, 300),
                                 part(B::happycat, 1000, 1e+3, 50, 400),
                                 part(B::expanded_schaffer_f6, 10000, 2e+7, 60, 500)},
                                2800, all_dims));
        r.push_back(composition("Composition Function 9 (N = 3, of hybrids 5, 6, 7)",
                                {hybrid_part(h5, 10, 0), hybrid_part(h6, 30, 100), hybrid_part(h7, 50, 200)},
                                2900, hybrid_dims));
        r.push_back(composition("Composition Function 10 (N = 3, of hybrids 5, 8, 9)",
                                {hybrid_part(h5, 10, 0), hybrid_part(h8, 30, 100), hybrid_part(h9, 50, 200)},
                                3000, hybrid_dims));
        return r;
    }();
    return all;
}

} // namespace mhb::cec
