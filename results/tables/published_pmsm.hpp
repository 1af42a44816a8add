// The numbers Li, Wang and Ji (2017) published for the PMSM study, so that reports can print them
// beside what a study measured. Only data; the source is cited in published_pmsm.cpp.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace mhb {

// Per algorithm: identified Rs, Ld, Lq, psi_f and their % errors as printed (magnitudes).
struct PublishedIdentification {
    std::string_view algorithm; // "itlbo", "tlbo" or "pso"
    std::array<double, 4> identified;
    std::array<double, 4> error_pct;
};

struct PublishedFitness {
    std::string_view algorithm;
    double mean;
    double std;
};

// One operating condition of the paper (load torque in N m, speed in rpm).
struct PublishedCondition {
    double load;
    double speed;
    std::string_view table; // where the paper prints it, e.g. "Table 3"
    std::vector<PublishedIdentification> identification;
    std::vector<PublishedFitness> fitness; // Table 2: only for the first condition
};

inline constexpr std::array<std::string_view, 4> pmsm_parameter_names = {"Rs", "Ld", "Lq", "psi"};
// The motor's true parameters (the paper's Table 1).
inline constexpr std::array<double, 4> pmsm_true_parameters = {0.330, 0.00324, 0.00324, 0.0776};

const std::vector<PublishedCondition>& published_pmsm_conditions();

// The condition with this load and speed, if the paper has one.
const PublishedCondition* find_published_condition(double load, double speed);

} // namespace mhb
