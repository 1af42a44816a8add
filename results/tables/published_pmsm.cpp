// Source: Li Jie, Wang Yan, Ji Zhicheng, "Permanent Magnet Synchronous Motor Parameter
// Identification Based on Improved Teaching-Learning-Based Optimization", Journal of System
// Simulation 29(2):393-401, 2017, DOI 10.16182/j.issn1004731x.joss.201702022.
// Table 2 (fitness mean and standard deviation over 20 runs, 2 N m / 2500 rpm), Table 3 (the same
// condition's identified parameters and % errors) and Table 4 (all three conditions; its first
// block repeats Table 3). Numbers are copied as printed; the % errors are magnitudes.
#include "results/tables/published_pmsm.hpp"

namespace mhb {

const std::vector<PublishedCondition>& published_pmsm_conditions() {
    static const std::vector<PublishedCondition> conditions = {
        {2.0,
         2500.0,
         "Tables 2 and 3",
         {{"itlbo", {0.3325, 0.00327, 0.00329, 0.0779}, {0.8, 0.9, 1.6, 0.4}},
          {"tlbo", {0.3215, 0.00363, 0.00337, 0.0811}, {2.6, 12.1, 4.1, 5.0}},
          {"pso", {0.3475, 0.00366, 0.00340, 0.0763}, {5.3, 12.9, 5.0, 2.1}}},
         {{"itlbo", 3.9904, 0.0725}, {"tlbo", 4.9905, 1.6258}, {"pso", 5.5904, 1.6625}}},
        {3.0,
         2500.0,
         "Table 4",
         {{"itlbo", {0.3315, 0.00326, 0.00320, 0.0778}, {0.5, 0.6, 1.2, 0.3}},
          {"tlbo", {0.3521, 0.00360, 0.00339, 0.0820}, {6.7, 11.1, 4.7, 5.7}},
          {"pso", {0.3455, 0.00367, 0.00339, 0.0775}, {4.7, 13.3, 4.6, 0.2}}},
         {}},
        {2.0,
         2000.0,
         "Table 4",
         {{"itlbo", {0.3425, 0.00336, 0.00338, 0.0785}, {3.8, 3.7, 4.3, 1.2}},
          {"tlbo", {0.3615, 0.00370, 0.00337, 0.0845}, {9.6, 14.2, 4.0, 8.9}},
          {"pso", {0.3638, 0.00375, 0.00346, 0.0810}, {10.3, 15.8, 6.8, 4.4}}},
         {}},
    };
    return conditions;
}

const PublishedCondition* find_published_condition(double load, double speed) {
    for (const auto& c : published_pmsm_conditions())
        if (c.load == load && c.speed == speed)
            return &c;
    return nullptr;
}

} // namespace mhb
