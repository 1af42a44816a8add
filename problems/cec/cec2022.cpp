// The 12 functions of CEC 2022 as the official cec22_test_func.cpp defines them
// (../shared/cec/README.md, sections 3-4); where the technical report differs, the code wins.
#include "problems/cec/cec_recipe_helpers.hpp"

namespace mhb::cec {

const std::vector<FunctionRecipe>& cec2022_recipes() {
    using namespace recipe;
    using B = Basic;
    static const std::vector<FunctionRecipe> all = [] {
        const std::vector<int> all_dims{2, 10, 20};
        const std::vector<int> hybrid_dims{10, 20}; // no D = 2 shuffle data
        std::vector<FunctionRecipe> r;
        r.push_back(simple("Shifted and Rotated Zakharov", B::zakharov, 300, all_dims));
        r.push_back(simple("Shifted and Rotated Rosenbrock", B::rosenbrock, 400, all_dims));
        // README Q2: the code computes Schaffer F7 on x - o, unrotated (the report: Expanded Schaffer F6).
        r.push_back(
            simple("Shifted Schaffer F7", B::schaffer_f7, 600, all_dims, false,
                   "the report names Expanded Schaffer F6; the code computes Schaffer F7, unrotated"));
        // README Q3: the code's rounding step is lost, so this is Rastrigin with F4's own data.
        r.push_back(simple("Shifted and Rotated Non-Continuous Rastrigin", B::rastrigin, 800, all_dims, true,
                           "the code's rounding step has no effect: it is Rastrigin"));
        r.push_back(simple("Shifted and Rotated Levy", B::levy_2022, 900, all_dims));
        r.push_back(hybrid("Hybrid Function 1 (N = 3)",
                           {{B::bent_cigar, B::hgbat, B::rastrigin}, {0.4, 0.4, 0.2}}, 1800, hybrid_dims));
        // README Q1: the Schaffer F7 group reads the first entries of the permuted vector.
        r.push_back(hybrid("Hybrid Function 2 (N = 6)",
                           {{B::hgbat, B::katsuura, B::ackley, B::rastrigin, B::schwefel, B::schaffer_f7},
                            {0.1, 0.2, 0.2, 0.2, 0.1, 0.2}},
                           2000, hybrid_dims));
        r.push_back(hybrid("Hybrid Function 3 (N = 5)",
                           {{B::katsuura, B::happycat, B::griewank_rosenbrock, B::schwefel, B::ackley},
                            {0.3, 0.2, 0.2, 0.1, 0.2}},
                           2200, hybrid_dims));
        r.push_back(
            composition("Composition Function 1 (N = 5)",
                        {part(B::rosenbrock, 10000, 1e+4, 10, 0), part(B::ellipsoid, 10000, 1e+10, 20, 200),
                         part(B::bent_cigar, 10000, 1e+30, 30, 300), part(B::discus, 10000, 1e+10, 40, 100),
                         part(B::ellipsoid, 10000, 1e+10, 50, 400, false)},
                        2300, all_dims, "lambda as in the code, not the report"));
        r.push_back(composition("Composition Function 2 (N = 3)",
                                {part(B::schwefel, 1, 1, 20, 0, false), part(B::rastrigin, 1, 1, 10, 200),
                                 part(B::hgbat, 1, 1, 10, 100)},
                                2400, all_dims));
        r.push_back(
            composition("Composition Function 3 (N = 5)",
                        {part(B::expanded_schaffer_f6, 10000, 2e+7, 20, 0), part(B::schwefel, 1, 1, 20, 200),
                         part(B::griewank, 1000, 100, 30, 300), part(B::rosenbrock, 1, 1, 30, 400),
                         part(B::rastrigin, 10000, 1e+3, 20, 200)},
                        2600, all_dims, "lambda as in the code, not the report"));
        r.push_back(composition(
            "Composition Function 4 (N = 6)",
            {part(B::hgbat, 10000, 1000, 10, 0), part(B::rastrigin, 10000, 1e+3, 20, 300),
             part(B::schwefel, 10000, 4e+3, 30, 500), part(B::bent_cigar, 10000, 1e+30, 40, 100),
             part(B::ellipsoid, 10000, 1e+10, 50, 400), part(B::expanded_schaffer_f6, 10000, 2e+7, 60, 200)},
            2700, all_dims));
        return r;
    }();
    return all;
}

} // namespace mhb::cec
