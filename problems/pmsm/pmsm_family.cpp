// Registration of the `pmsm` problem family: identification of Rs, Ld, Lq, psi (and optionally
// the inverter's dead-time voltage) of a PMSM, with three model fidelities:
//   model=steady  eq. 11 of Li, Wang and Ji (2017) on settled plateaus (convex; exact f*),
//   model=dynamic the discrete dq voltage equations with di/dt on transient data (linear; exact f*),
//   model=output  output error: the currents simulated from the measured voltages and speed
//                 (nonlinear, non-convex; f* is a best known value).
// The data are a user's dataset files (`data=a.csv+b.csv`) or the built-in drive simulator of any
// motor (the paper's by default) at one or more operating conditions. They are made or read
// once, when the problem is created; the same spec gives the same data bit for bit.
#include <cmath>
#include <string>
#include <vector>

#include "problems/core/bound_text.hpp"
#include "problems/pmsm/dynamic_model.hpp"
#include "problems/pmsm/linear_model_problem.hpp"
#include "problems/pmsm/output_error_problem.hpp"
#include "problems/pmsm/pmsm_sources.hpp"
#include "problems/pmsm/steady_state_problem.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

// `lo:hi` with finite lo < hi, e.g. `rs=0:1`.
void parse_bound(const ParameterValues& p, const char* key, Eigen::Index index, Box& box) {
    parse_bound_text("pmsm", key, p.text(key), "0:0.5", box.lower[index], box.upper[index]);
}

// The search box: the paper's for the paper's motor or when nothing is known of the motor, else
// [0, 3 x nominal] from the motor's parameters (the simulated motor's, or the data's metadata);
// the dead-time voltage in [0, 20] V; then any bound the spec gives.
Box search_box(const ParameterValues& p, const std::optional<Eigen::Vector4d>& nominal, bool dead_time) {
    Box box = pmsm::paper_bounds();
    if (nominal && *nominal != pmsm::paper_motor().identified()) {
        box.lower.setZero();
        box.upper = 3.0 * nominal->cwiseAbs();
    }
    if (dead_time) {
        box.lower.conservativeResize(5);
        box.upper.conservativeResize(5);
        box.lower[4] = 0.0;
        box.upper[4] = 20.0;
    }
    const char* keys[] = {"rs", "ld", "lq", "psi", "vdt"};
    for (Eigen::Index j = 0; j < box.dimension(); ++j)
        if (p.given(keys[j]))
            parse_bound(p, keys[j], j, box);
    if (!dead_time && p.given("vdt"))
        throw std::invalid_argument("pmsm: 'vdt' bounds the dead-time voltage, fitted only with fit_vdt=on");
    return box;
}

// A motor parameter: the spec's value, else the named motor's.
void motor_value(const ParameterValues& p, const char* key, double& value) {
    if (p.given(key))
        value = p.real(key);
}

pmsm::SimulatorConfig simulator_config(const ParameterValues& p, const std::string& model) {
    pmsm::SimulatorConfig config;
    config.motor = p.text("motor") == "ipm" ? pmsm::ipm_motor() : pmsm::paper_motor();
    motor_value(p, "motor_rs", config.motor.Rs);
    motor_value(p, "motor_ld", config.motor.Ld);
    motor_value(p, "motor_lq", config.motor.Lq);
    motor_value(p, "motor_psi", config.motor.psi);
    motor_value(p, "inertia", config.motor.J);
    motor_value(p, "friction", config.motor.B);
    if (p.given("pole_pairs"))
        config.motor.pole_pairs = static_cast<int>(p.integer("pole_pairs"));
    config.vdc = p.real("vdc");
    config.current_bandwidth = p.real("wc");
    config.speed_bandwidth = p.real("ws");
    config.iq_max = p.real("iq_max");
    config.condition.speed_rpm = p.real("speed");
    config.condition.load_Nm = p.real("load");
    config.noise_i = p.real("noise_i");
    config.noise_u = p.real("noise_u");
    config.seed = static_cast<std::uint64_t>(p.integer("seed"));
    config.samples_per_state = static_cast<int>(p.integer("n"));
    config.dead_time = p.real("deadtime");
    config.delay_periods = static_cast<int>(p.integer("delay"));
    config.adc_bits = static_cast<int>(p.integer("adc_bits"));
    config.stator_frame_hold = p.text("hold") == "stator";
    const std::string& window = p.text("window");
    config.window = window == "steady" || (window == "auto" && model == "steady")
                        ? pmsm::SimulatedWindow::steady
                        : pmsm::SimulatedWindow::transient;
    return config;
}

pmsm::PmsmSources sources(const ParameterValues& p, const std::string& model) {
    if (p.has("data")) {
        std::string clash;
        for (const char* key : {"speed",   "load",     "conditions", "noise_i",  "noise_u",   "seed",
                                "n",       "deadtime", "delay",      "adc_bits", "hold",      "window",
                                "motor",   "motor_rs", "motor_ld",   "motor_lq", "motor_psi", "pole_pairs",
                                "inertia", "friction", "vdc",        "wc",       "ws",        "iq_max"})
            if (p.given(key))
                clash += (clash.empty() ? "" : ", ") + std::string(key);
        if (!clash.empty())
            throw std::invalid_argument("pmsm: 'data' reads datasets; the simulator parameters (" + clash +
                                        ") cannot be given with it");
        pmsm::DatasetReadOptions options;
        options.injection_threshold = p.real("id_threshold");
        options.require_both_states = model == "steady";
        return pmsm::read_sources(p.text("data"), options);
    }
    if (p.has("conditions") && (p.given("speed") || p.given("load")))
        throw std::invalid_argument("pmsm: give either 'conditions' or 'speed' and 'load', not both");
    const pmsm::SimulatorConfig config = simulator_config(p, model);
    return pmsm::simulate_sources(config, p.has("conditions")
                                              ? pmsm::parse_conditions(p.text("conditions"))
                                              : std::vector<pmsm::OperatingCondition>{config.condition});
}

// The true parameters of the model's coordinates, when the data's metadata give them.
std::optional<Eigen::VectorXd> truth(const pmsm::PmsmSources& data, bool dead_time) {
    const auto nominal = data.nominal_parameters();
    if (!nominal)
        return std::nullopt;
    Eigen::VectorXd x(dead_time ? 5 : 4);
    x.head<4>() = *nominal;
    if (dead_time)
        x[4] = pmsm::dead_time_voltage(data.datasets.front());
    return x;
}

std::unique_ptr<Problem> make_pmsm(const ParameterValues& p) {
    const std::string& model = p.text("model");
    const bool dead_time = p.boolean("fit_vdt");
    if (model == "steady") {
        std::string clash;
        for (const char* key : {"fit_vdt", "vdt", "smooth", "substeps"})
            if (p.given(key))
                clash += (clash.empty() ? "" : ", ") + std::string(key);
        if (!clash.empty())
            throw std::invalid_argument("pmsm: " + clash +
                                        " apply to model=dynamic or model=output, not steady");
    } else {
        for (const char* key : {"w1", "w2", "w3", "w4", "fitness", "settle"})
            if (p.given(key))
                throw std::invalid_argument(std::string("pmsm: '") + key + "' applies to model=steady only");
    }
    pmsm::PmsmSources data = sources(p, model);
    Box box = search_box(p, data.nominal_parameters(), dead_time);

    std::unique_ptr<Problem> problem;
    if (model == "steady") {
        const pmsm::FitnessWeights weights{p.real("w1"), p.real("w2"), p.real("w3"), p.real("w4")};
        const auto evaluation = p.text("fitness") == "direct" ? pmsm::FitnessEvaluation::direct
                                                              : pmsm::FitnessEvaluation::expanded;
        auto steady = std::make_unique<pmsm::SteadyStateProblem>(
            pmsm::pair_samples(data.datasets, data.names, weights, p.real("settle")),
            data.nominal_parameters(), std::move(box), evaluation);
        steady->set_data_files(data.files);
        problem = std::move(steady);
    } else if (model == "dynamic") {
        pmsm::DynamicModelOptions options;
        options.fit_dead_time = dead_time;
        options.smoothing = static_cast<int>(p.integer("smooth"));
        auto dynamic = std::make_unique<pmsm::LinearModelProblem>(
            pmsm::dynamic_model(data.datasets, data.names, options), std::move(box), truth(data, dead_time));
        dynamic->set_data_files(data.files);
        problem = std::move(dynamic);
    } else {
        // The best known optimum is refined from the dynamic least-squares estimate (when the
        // data determine it) and from the true values (when known).
        std::vector<Eigen::VectorXd> starts;
        try {
            pmsm::DynamicModelOptions options;
            options.fit_dead_time = dead_time;
            const pmsm::LinearFit fit =
                pmsm::fit_linear_model(pmsm::dynamic_model(data.datasets, data.names, options));
            if (fit.rank == fit.theta.size())
                starts.push_back(fit.theta);
        } catch (const std::invalid_argument&) {
            // No consecutive rows for the dynamic model: the other starts remain.
        }
        const auto true_values = truth(data, dead_time);
        if (true_values)
            starts.push_back(*true_values);
        if (starts.empty())
            starts.push_back(0.5 * (box.lower + box.upper));
        pmsm::OutputErrorOptions options;
        options.fit_dead_time = dead_time;
        options.substeps = static_cast<int>(p.integer("substeps"));
        auto output = std::make_unique<pmsm::OutputErrorProblem>(
            pmsm::OutputErrorModel(data.datasets, data.names, options), std::move(box), true_values,
            std::move(starts));
        output->set_data_files(data.files);
        problem = std::move(output);
    }
    return problem;
}

} // namespace

void register_pmsm(ProblemRegistry& registry) {
    registry.add(
        {"pmsm",
         1,
         "PMSM identification of Rs, Ld, Lq, psi [, Vdt] from dq data: steady (eq. 11), dynamic (di/dt) or "
         "output-error model",
         "Li, Wang and Ji (2017), PMSM parameter identification based on improved TLBO",
         {ParameterInfo::text(
              "data", "",
              "dataset CSV files joined by '+' (t,ud,uq,id,iq,omega[,injected]), fitted jointly; if "
              "absent the drive is simulated"),
          ParameterInfo::choice(
              "model", "steady", {"steady", "dynamic", "output"},
              "steady: eq. 11 on settled plateaus (the paper); dynamic: the discrete dq voltage "
              "equations with di/dt on transients; output: simulated against measured currents"),
          ParameterInfo::real("speed", 2500.0, 0.0, 20000.0,
                              "simulated speed reference, rpm (paper: 2500, 2000)")
              .open_below(),
          ParameterInfo::real(
              "load", 2.0, -1000.0, 1000.0,
              "simulated load torque, N m (paper: 2, 3; |load| < Kt iq_max, 4.19 for the paper's motor)"),
          ParameterInfo::text(
              "conditions", "",
              "simulate several conditions, fitted jointly: SPEED@LOAD joined by '+' (rpm@N m), or "
              "'paper' for 2500@2+2500@3+2000@2"),
          ParameterInfo::choice(
              "motor", "paper", {"paper", "ipm"},
              "simulated motor: the paper's (Table 1) or an interior-PM one (0.9 ohm, 6/14 mH, 0.17 "
              "Wb, p = 3); the motor_* parameters override its values"),
          ParameterInfo::real("motor_rs", pmsm::paper_motor().Rs, 0.0, 100.0,
                              "simulated Rs, ohm (default: the motor's)")
              .open_below(),
          ParameterInfo::real("motor_ld", pmsm::paper_motor().Ld, 0.0, 10.0,
                              "simulated Ld, H (default: the motor's)")
              .open_below(),
          ParameterInfo::real("motor_lq", pmsm::paper_motor().Lq, 0.0, 10.0,
                              "simulated Lq, H (default: the motor's)")
              .open_below(),
          ParameterInfo::real("motor_psi", pmsm::paper_motor().psi, 0.0, 100.0,
                              "simulated psi, Wb (default: the motor's)")
              .open_below(),
          ParameterInfo::integer("pole_pairs", pmsm::paper_motor().pole_pairs, 1, 100,
                                 "simulated pole pairs p (default: the motor's)"),
          ParameterInfo::real("inertia", pmsm::paper_motor().J, 0.0, 1e6,
                              "simulated rotor inertia J, kg m^2 (default: the motor's)")
              .open_below(),
          ParameterInfo::real("friction", pmsm::paper_motor().B, 0.0, 1e6,
                              "simulated viscous friction B, N m s/rad (default: the motor's)"),
          ParameterInfo::real("vdc", pmsm::SimulatorConfig{}.vdc, 0.0, 1e5,
                              "simulated DC bus, V (the voltage limit is vdc / sqrt(3))")
              .open_below(),
          ParameterInfo::real("wc", pmsm::SimulatorConfig{}.current_bandwidth, 0.0, 1e6,
                              "simulated current-loop bandwidth, rad/s (Kp = wc L, Ki = wc Rs)")
              .open_below(),
          ParameterInfo::real("ws", pmsm::SimulatorConfig{}.speed_bandwidth, 0.0, 1e6,
                              "simulated speed-loop bandwidth, rad/s (Kp_w = ws J / Kt, Ki_w = Kp_w ws / 3)")
              .open_below(),
          ParameterInfo::real("iq_max", pmsm::SimulatorConfig{}.iq_max, 0.0, 1e5,
                              "simulated limit of the q-current reference, A")
              .open_below(),
          ParameterInfo::choice(
              "window", "auto", {"auto", "steady", "transient"},
              "simulated window: the settled ends of two plateaus, or the 2n samples around the "
              "injection step; auto: steady for model=steady, else transient"),
          ParameterInfo::real("noise_i", 0.0, 0.0, 10.0, "simulated current noise (std), A"),
          ParameterInfo::real("noise_u", 0.0, 0.0, 100.0, "simulated logged-voltage noise (std), V"),
          ParameterInfo::integer("seed", 1, 0, 9007199254740992LL, "seed of the simulated noise"),
          ParameterInfo::integer("n", 300, 2, 500, "simulated samples per injection state (paper: 300)"),
          ParameterInfo::real("deadtime", 0.0, 0.0, 1e-5,
                              "simulated inverter dead time, s (0: ideal inverter)"),
          ParameterInfo::integer("delay", 0, 0, 1, "simulated computation delay, control periods"),
          ParameterInfo::integer("adc_bits", 0, 0, 24,
                                 "simulated phase-current ADC bits over +-20 A (0: off)"),
          ParameterInfo::choice(
              "hold", "dq", {"dq", "stator"},
              "simulated voltage hold: rotor dq frame (ideal) or stator frame (a real inverter "
              "without angle compensation: the vector lags by omega Ts / 2)"),
          ParameterInfo::real(
              "id_threshold", 1.0, 0.0, 1e6,
              "with data= and no 'injected' column: |id| above this (A) marks the injected state")
              .open_below(),
          ParameterInfo::real(
              "settle", pmsm::default_settle_time, 0.0, 10.0,
              "steady: samples less than this (s) after a switch of the injection state are not "
              "used; the last n settled samples of each state are paired"),
          ParameterInfo::real("w1", 0.25, 0.0, 1e6,
                              "weight of the d-axis residual, id = 0 state (paper: 0.25)"),
          ParameterInfo::real("w2", 0.25, 0.0, 1e6,
                              "weight of the q-axis residual, id = 0 state (paper: 0.25)"),
          ParameterInfo::real("w3", 0.25, 0.0, 1e6,
                              "weight of the d-axis residual, injected state (paper: 0.25)"),
          ParameterInfo::real("w4", 0.25, 0.0, 1e6,
                              "weight of the q-axis residual, injected state (paper: 0.25)"),
          ParameterInfo::choice(
              "fitness", "expanded", {"expanded", "direct"},
              "how eq. 11 is evaluated: constant-time expansion about the optimum, or the sum "
              "over the samples (same function, ~1e-13 relative apart)"),
          ParameterInfo::boolean(
              "fit_vdt", false,
              "dynamic, output: fit a fifth parameter, the inverter's dead-time voltage Vdt (V), "
              "so that it is not mistaken for Rs"),
          ParameterInfo::integer(
              "smooth", 0, 0, 50,
              "dynamic: half-width K of a centred moving average (2K + 1 samples) on every "
              "signal before di/dt is formed; 0: none"),
          ParameterInfo::integer("substeps", 2, 1, 1000,
                                 "output: RK4 steps per sampling period of the simulation"),
          ParameterInfo::text("rs", "",
                              "search bounds of Rs, ohm, lo:hi (default: paper 0:0.5, or 0:3 x nominal)"),
          ParameterInfo::text("ld", "",
                              "search bounds of Ld, H, lo:hi (default: paper 0:0.01, or 0:3 x nominal)"),
          ParameterInfo::text("lq", "",
                              "search bounds of Lq, H, lo:hi (default: paper 0:0.01, or 0:3 x nominal)"),
          ParameterInfo::text("psi", "",
                              "search bounds of psi, Wb, lo:hi (default: paper 0:0.1, or 0:3 x nominal)"),
          ParameterInfo::text("vdt", "", "search bounds of the dead-time voltage, V, lo:hi (default 0:20)")},
         make_pmsm});
}

} // namespace mhb
