#include "problems/pmsm/drive_simulator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/core/rng.hpp"

namespace mhb::pmsm {

ControllerGains pole_zero_gains(const MotorParameters& motor, double current_bandwidth,
                                double speed_bandwidth) {
    ControllerGains g;
    g.kp_d = current_bandwidth * motor.Ld;
    g.ki_d = current_bandwidth * motor.Rs;
    g.kp_q = current_bandwidth * motor.Lq;
    g.ki_q = current_bandwidth * motor.Rs;
    g.kp_w = speed_bandwidth * motor.J / motor.torque_constant();
    g.ki_w = g.kp_w * speed_bandwidth / 3.0;
    return g;
}

namespace {

void require(bool ok, const std::string& what) {
    if (!ok)
        throw std::invalid_argument("pmsm simulator: " + what);
}

int whole_periods(double duration, double Ts) {
    return static_cast<int>(std::lround(duration / Ts));
}

} // namespace

void SimulatorConfig::validate() const {
    const MotorParameters& m = motor;
    require(m.Rs > 0 && m.Ld > 0 && m.Lq > 0 && m.psi > 0 && m.J > 0 && m.B >= 0 && m.pole_pairs > 0,
            "motor parameters must be positive (B >= 0)");
    require(std::isfinite(condition.speed_rpm) && condition.speed_rpm > 0, "speed must be > 0 rpm");
    require(std::isfinite(condition.load_Nm), "load must be finite");
    require(current_bandwidth > 0 && speed_bandwidth > 0, "bandwidths must be > 0");
    require(iq_max > 0 && vdc > 0 && Ts > 0 && settle_time >= 0 && plateau > 0,
            "limits and times must be > 0");
    require(substeps >= 1 && substeps <= 100000, "substeps must be in [1, 100000]");
    require(std::isfinite(injection_current) && injection_current != 0.0,
            "injection current must be non-zero");
    require(samples_per_state >= 1 && samples_per_state <= plateau_steps(),
            "samples per state must be in [1, " + std::to_string(plateau_steps()) + "] (one plateau of " +
                format_real(plateau) + " s at Ts = " + format_real(Ts) + " s)");
    require(noise_i >= 0 && noise_u >= 0, "noise levels must be >= 0");
    require(adc_bits >= 0 && adc_bits <= 24 && adc_range > 0, "ADC bits must be in [0, 24] with range > 0");
    require(dead_time >= 0 && dead_time < Ts, "dead time must be in [0, Ts)");
    require(delay_periods == 0 || delay_periods == 1, "delay must be 0 or 1 period");
    const double kt = motor.torque_constant();
    require(std::fabs(condition.load_Nm) < kt * iq_max, "load torque exceeds Kt * iq_max");
}

int SimulatorConfig::plateau_steps() const {
    return whole_periods(plateau, Ts);
}
int SimulatorConfig::settle_steps() const {
    return whole_periods(settle_time, Ts);
}

namespace {

// Plant state: currents, electrical speed and electrical angle.
struct PlantState {
    double id = 0, iq = 0, omega = 0, theta = 0;
};

constexpr double two_thirds_pi = 2.0 * pi / 3.0;

// Amplitude-invariant abc -> dq of a balanced or unbalanced set (the zero sequence drops out).
void abc_to_dq(double a, double b, double c, double theta, double& d, double& q) {
    const double alpha = (2.0 * a - b - c) / 3.0;
    const double beta = (b - c) / std::sqrt(3.0);
    const double co = std::cos(theta);
    const double si = std::sin(theta);
    d = alpha * co + beta * si;
    q = -alpha * si + beta * co;
}

void dq_to_abc(double d, double q, double theta, double& a, double& b, double& c) {
    a = d * std::cos(theta) - q * std::sin(theta);
    b = d * std::cos(theta - two_thirds_pi) - q * std::sin(theta - two_thirds_pi);
    c = -a - b;
}

class Drive {
public:
    explicit Drive(const SimulatorConfig& config)
        : cfg_(config), m_(config.motor),
          gains_(pole_zero_gains(config.motor, config.current_bandwidth, config.speed_bandwidth)),
          current_noise_(mix64(config.seed ^ stable_hash("pmsm current noise"))),
          voltage_noise_(mix64(config.seed ^ stable_hash("pmsm voltage noise"))) {
        omega_ref_ = electrical_speed(cfg_.condition.speed_rpm, m_.pole_pairs);
        // The exact equilibrium with id = 0 at the reference speed.
        const double omega_m = omega_ref_ / m_.pole_pairs;
        const double iq0 = (cfg_.condition.load_Nm + m_.B * omega_m) / m_.torque_constant();
        x_ = PlantState{0.0, iq0, omega_ref_, 0.0};
        int_w_ = iq0;
        int_d_ = 0.0;
        int_q_ = m_.Rs * iq0;
        u_prev_d_ = -omega_ref_ * m_.Lq * iq0;
        u_prev_q_ = m_.Rs * iq0 + omega_ref_ * m_.psi;
        angle_prev_ = -omega_ref_ * cfg_.Ts; // that command was set one period before t = 0
        umax_ = cfg_.vdc / std::sqrt(3.0);
        dead_voltage_ = cfg_.vdc * cfg_.dead_time / cfg_.Ts;
    }

    [[nodiscard]] double omega_ref() const { return omega_ref_; }
    [[nodiscard]] double umax() const { return umax_; }
    [[nodiscard]] const ControllerGains& gains() const { return gains_; }

    // Whether period k is in an injected plateau.
    [[nodiscard]] bool injected(int k) const {
        const int settle = cfg_.settle_steps();
        return k >= settle && ((k - settle) / cfg_.plateau_steps()) % 2 == 1;
    }

    // One control period k: measure, control, apply over [t_k, t_k + Ts), and return the logged row.
    void step(int k, Dataset& log) {
        // k / (1 / Ts) rather than k * Ts: 0.3202, not 0.32020000000000004, in the written file.
        const double t = static_cast<double>(k) / (1.0 / cfg_.Ts);
        double id_m = x_.id;
        double iq_m = x_.iq;
        if (cfg_.noise_i > 0) {
            id_m += cfg_.noise_i * current_noise_.normal();
            iq_m += cfg_.noise_i * current_noise_.normal();
        }
        if (cfg_.adc_bits > 0)
            quantise(id_m, iq_m);
        const double omega_m = x_.omega;

        // Speed PI on the mechanical speed error, giving iq*; conditional integration anti-windup.
        const double e_w = (omega_ref_ - omega_m) / m_.pole_pairs;
        double iq_ref = gains_.kp_w * e_w + int_w_;
        if (std::fabs(iq_ref) > cfg_.iq_max) {
            iq_ref = std::copysign(cfg_.iq_max, iq_ref);
            if (e_w * iq_ref < 0)
                int_w_ += gains_.ki_w * cfg_.Ts * e_w;
        } else {
            int_w_ += gains_.ki_w * cfg_.Ts * e_w;
        }
        const bool inject = injected(k);
        const double id_ref = inject ? cfg_.injection_current : 0.0;

        // Current PIs with decoupling feed-forward from the controller's (nominal) parameters.
        const double e_d = id_ref - id_m;
        const double e_q = iq_ref - iq_m;
        double ud = gains_.kp_d * e_d + int_d_ - omega_m * m_.Lq * iq_m;
        double uq = gains_.kp_q * e_q + int_q_ + omega_m * (m_.Ld * id_m + m_.psi);
        const double magnitude = std::hypot(ud, uq);
        if (magnitude > umax_) {
            ud *= umax_ / magnitude; // the DC bus limits the vector; hold the integrators
            uq *= umax_ / magnitude;
        } else {
            int_d_ += gains_.ki_d * cfg_.Ts * e_d;
            int_q_ += gains_.ki_q * cfg_.Ts * e_q;
        }

        double logged_d = ud;
        double logged_q = uq;
        if (cfg_.noise_u > 0) {
            logged_d += cfg_.noise_u * voltage_noise_.normal();
            logged_q += cfg_.noise_u * voltage_noise_.normal();
        }
        log.push_back(t, logged_d, logged_q, id_m, iq_m, omega_m, inject);

        double apply_d = ud;
        double apply_q = uq;
        hold_angle_ = x_.theta; // the angle the controller's inverse Park transform uses
        if (cfg_.delay_periods == 1) {
            apply_d = u_prev_d_;
            apply_q = u_prev_q_;
            std::swap(hold_angle_, angle_prev_);
            u_prev_d_ = ud;
            u_prev_q_ = uq;
        }
        const double h = cfg_.Ts / cfg_.substeps;
        for (int s = 0; s < cfg_.substeps; ++s)
            rk4(apply_d, apply_q, h);
    }

private:
    // Phase currents through an ADC of adc_bits over [-range, range] (c = -a - b), back to dq.
    void quantise(double& id_m, double& iq_m) const {
        double a = 0, b = 0, c = 0;
        dq_to_abc(id_m, iq_m, x_.theta, a, b, c);
        const double lsb = 2.0 * cfg_.adc_range / std::ldexp(1.0, cfg_.adc_bits);
        a = std::round(std::clamp(a, -cfg_.adc_range, cfg_.adc_range) / lsb) * lsb;
        b = std::round(std::clamp(b, -cfg_.adc_range, cfg_.adc_range) / lsb) * lsb;
        abc_to_dq(a, b, -a - b, x_.theta, id_m, iq_m);
    }

    // The dq voltage error of an inverter with dead time, from the signs of the phase currents.
    void dead_time_error(const PlantState& s, double& ed, double& eq) const {
        double a = 0, b = 0, c = 0;
        dq_to_abc(s.id, s.iq, s.theta, a, b, c);
        auto sign = [](double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); };
        abc_to_dq(-dead_voltage_ * sign(a), -dead_voltage_ * sign(b), -dead_voltage_ * sign(c), s.theta, ed,
                  eq);
    }

    [[nodiscard]] PlantState derivative(const PlantState& s, double ud, double uq) const {
        if (cfg_.stator_frame_hold) {
            // The inverter holds the stator-frame vector set with the angle at the start of the
            // period; seen from the rotor it turns back by the angle travelled since.
            const double lag = s.theta - hold_angle_;
            const double co = std::cos(lag);
            const double si = std::sin(lag);
            const double d_axis = co * ud + si * uq;
            uq = -si * ud + co * uq;
            ud = d_axis;
        }
        PlantState d;
        d.id = (ud - m_.Rs * s.id + s.omega * m_.Lq * s.iq) / m_.Ld;
        d.iq = (uq - m_.Rs * s.iq - s.omega * m_.Ld * s.id - s.omega * m_.psi) / m_.Lq;
        const double torque = 1.5 * m_.pole_pairs * (m_.psi * s.iq + (m_.Ld - m_.Lq) * s.id * s.iq);
        d.omega = m_.pole_pairs * (torque - cfg_.condition.load_Nm - m_.B * s.omega / m_.pole_pairs) / m_.J;
        d.theta = s.omega;
        return d;
    }

    static PlantState axpy(const PlantState& x, double a, const PlantState& d) {
        return {x.id + a * d.id, x.iq + a * d.iq, x.omega + a * d.omega, x.theta + a * d.theta};
    }

    void rk4(double ud, double uq, double h) {
        if (dead_voltage_ > 0) {
            double ed = 0, eq = 0;
            dead_time_error(x_, ed, eq); // held over the substep
            ud += ed;
            uq += eq;
        }
        const PlantState k1 = derivative(x_, ud, uq);
        const PlantState k2 = derivative(axpy(x_, 0.5 * h, k1), ud, uq);
        const PlantState k3 = derivative(axpy(x_, 0.5 * h, k2), ud, uq);
        const PlantState k4 = derivative(axpy(x_, h, k3), ud, uq);
        x_.id += h / 6.0 * (k1.id + 2.0 * k2.id + 2.0 * k3.id + k4.id);
        x_.iq += h / 6.0 * (k1.iq + 2.0 * k2.iq + 2.0 * k3.iq + k4.iq);
        x_.omega += h / 6.0 * (k1.omega + 2.0 * k2.omega + 2.0 * k3.omega + k4.omega);
        x_.theta += h / 6.0 * (k1.theta + 2.0 * k2.theta + 2.0 * k3.theta + k4.theta);
        x_.theta = std::remainder(x_.theta, 2.0 * pi);
    }

    const SimulatorConfig& cfg_;
    const MotorParameters& m_;
    ControllerGains gains_;
    Rng current_noise_;
    Rng voltage_noise_;
    PlantState x_;
    double omega_ref_ = 0;
    double umax_ = 0;
    double dead_voltage_ = 0;
    double int_w_ = 0, int_d_ = 0, int_q_ = 0;
    double u_prev_d_ = 0, u_prev_q_ = 0;
    double hold_angle_ = 0; // rotor angle with which the applied voltage was set
    double angle_prev_ = 0; // with the delay: the angle of the command waiting for the next period
};

} // namespace

namespace {

// The drive's log over its first `periods` control periods.
Dataset run_periods(Drive& drive, int periods) {
    Dataset log;
    log.reserve(static_cast<std::size_t>(periods));
    for (int k = 0; k < periods; ++k)
        drive.step(k, log);
    return log;
}

} // namespace

Dataset simulate_trace(const SimulatorConfig& config, int periods) {
    config.validate();
    if (periods < 0)
        throw std::invalid_argument("pmsm simulator: periods must be >= 0");
    Drive drive(config);
    return run_periods(drive, periods);
}

const char* to_string(SimulatedWindow window) {
    return window == SimulatedWindow::steady ? "steady" : "transient";
}

Dataset simulate_dataset(const SimulatorConfig& config) {
    config.validate();
    const int settle = config.settle_steps();
    const int plateau = config.plateau_steps();
    const int n = config.samples_per_state;
    // Third plateau (id = 0) ends at settle + 3P, fourth (injected) at settle + 4P; the transient
    // window is the n samples either side of the step between them.
    const int end_off = settle + 3 * plateau;
    const int end_on = settle + 4 * plateau;
    const bool transient = config.window == SimulatedWindow::transient;
    Drive drive(config);
    const Dataset all = run_periods(drive, transient ? end_off + n : end_on);

    Dataset out;
    out.reserve(2 * static_cast<std::size_t>(n));
    const std::vector<std::pair<int, int>> stretches =
        transient ? std::vector<std::pair<int, int>>{{end_off - n, end_off + n}}
                  : std::vector<std::pair<int, int>>{{end_off - n, end_off}, {end_on - n, end_on}};
    for (const auto& [begin, end] : stretches)
        for (int k = begin; k < end; ++k) {
            const auto i = static_cast<std::size_t>(k);
            out.push_back(all.t[i], all.ud[i], all.uq[i], all.id[i], all.iq[i], all.omega[i],
                          all.injected[i]);
        }

    const MotorParameters& m = config.motor;
    const ControllerGains& g = drive.gains();
    out.set_metadata("generator",
                     std::string("mhbench pmsm drive simulator (dq model, speed and current PI loops)"));
    out.set_metadata("Rs", m.Rs);
    out.set_metadata("Ld", m.Ld);
    out.set_metadata("Lq", m.Lq);
    out.set_metadata("psi", m.psi);
    out.set_metadata("p", static_cast<double>(m.pole_pairs));
    out.set_metadata("J", m.J);
    out.set_metadata("B", m.B);
    out.set_metadata("speed_rpm", config.condition.speed_rpm);
    out.set_metadata("load_Nm", config.condition.load_Nm);
    out.set_metadata("omega_ref_elec", drive.omega_ref());
    out.set_metadata("Vdc", config.vdc);
    out.set_metadata("umax", drive.umax());
    out.set_metadata("Ts", config.Ts);
    out.set_metadata("dt_plant", config.Ts / config.substeps);
    out.set_metadata("integrator", std::string("RK4"));
    out.set_metadata("zoh_frame", std::string(config.stator_frame_hold ? "stator" : "dq"));
    out.set_metadata("noise_i", config.noise_i);
    out.set_metadata("noise_u", config.noise_u);
    out.set_metadata("adc_bits", static_cast<double>(config.adc_bits));
    out.set_metadata("adc_range_A", config.adc_range);
    out.set_metadata("deadtime_s", config.dead_time);
    out.set_metadata("delay_periods", static_cast<double>(config.delay_periods));
    out.set_metadata("seed", std::to_string(config.seed));
    out.set_metadata("injection_A", config.injection_current);
    out.set_metadata("plateau_s", config.plateau);
    out.set_metadata("settle_s", config.settle_time);
    out.set_metadata("samples_per_state", static_cast<double>(n));
    out.set_metadata("window", std::string(to_string(config.window)));
    out.set_metadata("wc_current", config.current_bandwidth);
    out.set_metadata("ws_speed", config.speed_bandwidth);
    out.set_metadata("Kp_d", g.kp_d);
    out.set_metadata("Ki_d", g.ki_d);
    out.set_metadata("Kp_q", g.kp_q);
    out.set_metadata("Ki_q", g.ki_q);
    out.set_metadata("Kp_w", g.kp_w);
    out.set_metadata("Ki_w", g.ki_w);
    out.set_metadata("iq_max", config.iq_max);
    out.set_metadata("timing", std::string("u[k] applied on [t_k,t_k+Ts); id,iq,omega sampled at t_k"));
    out.set_metadata("units", std::string("s,V,V,A,A,electrical rad/s"));
    return out;
}

} // namespace mhb::pmsm
