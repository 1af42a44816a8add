// The permanent-magnet synchronous motor being identified and the condition it runs at.
// The named default is the motor of Li, Wang and Ji (2017), Table 1; B is not in the table and is
// a small viscous friction chosen here (the same value as the shared test data's simulator).
#pragma once

#include <Eigen/Core>

namespace mhb::pmsm {

struct MotorParameters {
    double Rs = 0.330;   // stator resistance, ohm
    double Ld = 3.24e-3; // d-axis inductance, H
    double Lq = 3.24e-3; // q-axis inductance, H
    double psi = 0.0776; // permanent-magnet flux linkage, Wb
    int pole_pairs = 2;  // p
    double J = 0.8e-5;   // rotor inertia, kg m^2
    double B = 1e-5;     // viscous friction, N m s/rad (not in the paper; small)

    // Torque constant Kt = 1.5 p psi (N m/A), amplitude-invariant dq frame.
    [[nodiscard]] double torque_constant() const { return 1.5 * pole_pairs * psi; }
    // The four identified parameters in the order of the identification problems: Rs, Ld, Lq, psi.
    [[nodiscard]] Eigen::Vector4d identified() const { return {Rs, Ld, Lq, psi}; }
};

// The paper's motor (Table 1): 2.6 kW, 4 A, 380 V, 2500 rpm.
inline MotorParameters paper_motor() {
    return MotorParameters{};
}

// An interior-PM motor (L_d != L_q, reluctance torque), the second motor of the shared test data
// (tests/data/pmsm/README.md): 0.9 ohm, 6 and 14 mH, 0.17 Wb, p = 3.
inline MotorParameters ipm_motor() {
    return MotorParameters{0.9, 6e-3, 14e-3, 0.17, 3, 2e-4, 1e-4};
}

// Where the drive runs: a constant speed reference and a constant load torque.
struct OperatingCondition {
    double speed_rpm = 2500.0; // mechanical speed reference, rpm
    double load_Nm = 2.0;      // load torque, N m
};

inline constexpr double pi = 3.14159265358979323846;

// Electrical angular speed (rad/s) of a mechanical speed in rpm.
inline double electrical_speed(double speed_rpm, int pole_pairs) {
    return speed_rpm * 2.0 * pi / 60.0 * pole_pairs;
}

} // namespace mhb::pmsm
