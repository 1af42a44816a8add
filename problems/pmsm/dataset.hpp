// A steady-state PMSM dataset: what the drive simulator writes and what a user brings from a real
// drive. One row per control period: t (s), ud, uq (V, applied from t to t + Ts), id, iq (A,
// measured at t), omega (electrical rad/s), and whether the -2 A d-axis injection was on.
// Metadata are free key=value pairs; Rs, Ld, Lq and psi, when present, are the true parameters.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mhb::pmsm {

struct Dataset {
    std::vector<double> t;
    std::vector<double> ud;
    std::vector<double> uq;
    std::vector<double> id;
    std::vector<double> iq;
    std::vector<double> omega;
    std::vector<bool> injected; // true: the d-axis current injection was on (eq. 4's second state)
    std::vector<std::pair<std::string, std::string>> metadata; // in the order written

    [[nodiscard]] std::size_t size() const { return t.size(); }
    void reserve(std::size_t n);
    void push_back(double t_k, double ud_k, double uq_k, double id_k, double iq_k, double omega_k,
                   bool injected_k);

    // The value of a metadata key, or nullptr.
    [[nodiscard]] const std::string* find_metadata(const std::string& key) const;
    // Sets (or replaces) a metadata key; numbers are written exactly (shortest round trip).
    void set_metadata(const std::string& key, std::string value);
    void set_metadata(const std::string& key, double value);

    // (Rs, Ld, Lq, psi) from the metadata when all four are present and numeric.
    [[nodiscard]] std::optional<Eigen::Vector4d> true_parameters() const;
    // Number of samples in each state: {id = 0, injected}.
    [[nodiscard]] std::pair<std::size_t, std::size_t> state_counts() const;
};

} // namespace mhb::pmsm
