// A simulator of a PMSM drive (the paper's motor by default, any motor by its parameters): the PMSM in the
// rotor dq frame (ARCHITECTURE.md section 10) with its mechanics, under field-oriented control - a speed PI
// loop giving the q-current reference, d and q current PI loops with decoupling feed-forward, and the DC-bus
// voltage limit - sampled and held every control period Ts = 100 us. It produces the datasets the
// identification problems are built from: settled plateaus for the steady-state model, a step transient for
// the dynamic ones.
//
// Discretisation. The controller runs once per period; the voltage it computes is held constant
// in the dq frame over [t_k, t_k + Ts) (an ideal average inverter with a zero-order hold); the
// plant is integrated over that period by classical RK4 with `substeps` steps (default 10, i.e.
// 10 us). The electrical poles of the motor are at about |R/L + j omega| < 1e3 rad/s and the
// electromechanical coupling near 1.2e3 rad/s, so h |lambda| ~ 0.012 and RK4's local error
// (h lambda)^5 / 120 is ~2e-12 per step: the 10 us and 1 us solutions differ by far less than a
// microvolt (tests/unit/problems/pmsm_simulator_test.cpp asserts the figure).
//
// Schedule. The drive starts at the exact equilibrium (id = 0, reference speed, the integrators
// holding the steady voltages), settles for `settle_time`, then the d-current reference alternates
// between 0 and `injection_current` every `plateau` (first 0, then injected, ...). The steady
// window takes the last n samples of the third plateau (id = 0) and of the fourth (injected),
// i.e. of the plateaus [settle + 2P, settle + 3P) and [settle + 3P, settle + 4P): two settled
// stretches with a jump in t between them. The transient window takes 2n consecutive samples
// around the step between them: the last n of the third plateau and the first n of the fourth,
// so the whole current (and speed) transient of the step is inside - the data of the dynamic and
// output-error models. Sample k pairs the voltage commanded for [t_k, t_k + Ts) with the
// currents and speed measured at t_k.
//
// Imperfections, each off by default: Gaussian noise on the measured currents (inside the loop,
// the controller sees it) and on the logged voltages (the motor receives the commanded voltage),
// a 12-bit-style ADC quantisation of the phase currents, inverter dead time (a per-phase voltage
// error -Vdc * t_dead / Ts * sign(i)), a one-period computation delay, and a stator-frame hold.
// With the default dq-frame hold a delay changes only the transients (a constant steady voltage
// is the same one period later); with the stator-frame hold the voltage vector lags the rotor by
// omega t within each period (by omega Ts / 2 on average, 1.5 omega Ts with the delay), the
// angle error a real inverter has unless the inverse Park transform is compensated. All
// randomness comes from `seed` through mhb::Rng (current and voltage noise on separate streams).
#pragma once

#include <cstdint>

#include "problems/pmsm/dataset.hpp"
#include "problems/pmsm/motor.hpp"

namespace mhb::pmsm {

// PI gains by pole-zero cancellation (ARCHITECTURE.md section 10): current loops Kp = wc L, Ki = wc Rs; speed
// loop Kp_w = ws J / Kt, Ki_w = Kp_w ws / 3, acting on the mechanical speed error (rad/s) to give iq*.
struct ControllerGains {
    double kp_d = 0, ki_d = 0, kp_q = 0, ki_q = 0; // V/A, V/(A s)
    double kp_w = 0, ki_w = 0;                     // A s/rad, A/rad
};
ControllerGains pole_zero_gains(const MotorParameters& motor, double current_bandwidth,
                                double speed_bandwidth);

// Which samples simulate_dataset() keeps (see the schedule above).
enum class SimulatedWindow { steady, transient };
const char* to_string(SimulatedWindow window);

struct SimulatorConfig {
    MotorParameters motor = paper_motor();
    OperatingCondition condition;
    double current_bandwidth = 3000.0; // wc, rad/s
    double speed_bandwidth = 800.0;    // ws, rad/s
    // A, limit of the q-current reference (not the rated 4 A, see ARCHITECTURE.md section 10)
    double iq_max = 18.0;
    double vdc = 540.0;              // V; the voltage vector is limited to Vdc / sqrt(3)
    double Ts = 1e-4;                // control and sampling period, s
    int substeps = 10;               // RK4 steps per period
    double settle_time = 0.2;        // s at id = 0 before the injection starts
    double plateau = 0.05;           // s per injection state
    double injection_current = -2.0; // A
    int samples_per_state = 300;     // n; at most one plateau's worth of samples
    double noise_i = 0.0;            // A, standard deviation on the measured id and iq
    double noise_u = 0.0;            // V, standard deviation on the logged ud and uq
    std::uint64_t seed = 1;
    int adc_bits = 0;               // 0: no quantisation
    double adc_range = 20.0;        // A, the ADC spans [-range, range]
    double dead_time = 0.0;         // s; 0: ideal inverter
    int delay_periods = 0;          // 0 or 1: the motor receives the previous period's voltage
    bool stator_frame_hold = false; // hold the voltage in the stator frame (a real inverter, no
                                    // angle compensation) instead of the rotor dq frame
    SimulatedWindow window = SimulatedWindow::steady;

    // Throws std::invalid_argument naming the first bad field.
    void validate() const;
    [[nodiscard]] int plateau_steps() const;
    [[nodiscard]] int settle_steps() const;
};

// Every control period from t = 0 for `periods` periods; `injected` is the reference state.
Dataset simulate_trace(const SimulatorConfig& config, int periods);

// The dataset of `config.window` (see the schedule above), with metadata describing the run.
Dataset simulate_dataset(const SimulatorConfig& config);

} // namespace mhb::pmsm
