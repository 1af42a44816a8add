// Registration of the `pmsm` problem family: steady-state identification of Rs, Ld, Lq, psi
// (Li, Wang and Ji 2017, eq. 11) either from a user's dataset (`data=FILE`) or from the built-in
// drive simulator at a given condition (`speed=`, `load=`, noise, `seed=`, `n=`). The data are
// made or read once, when the problem is created; the same spec gives the same data bit for bit.
#include <cmath>
#include <string>
#include <vector>

#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/drive_simulator.hpp"
#include "problems/pmsm/steady_state_problem.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

// `lo:hi` with finite lo < hi, e.g. `rs=0:1`.
void parse_bound(const ParameterValues& p, const char* key, Eigen::Index index, Box& box) {
    const std::string& text = p.text(key);
    const auto colon = text.find(':');
    double lo = 0, hi = 0;
    if (colon == std::string::npos || !parse_real(text.substr(0, colon), lo) ||
        !parse_real(text.substr(colon + 1), hi))
        throw std::invalid_argument(std::string("pmsm: parameter '") + key + "' = " + text +
                                    " is not of the form lo:hi (two finite numbers, e.g. 0:0.5)");
    if (!(lo < hi))
        throw std::invalid_argument(std::string("pmsm: parameter '") + key + "' = " + text +
                                    " needs lo < hi");
    box.lower[index] = lo;
    box.upper[index] = hi;
}

std::unique_ptr<Problem> make_pmsm(const ParameterValues& p) {
    Box box = pmsm::paper_bounds();
    parse_bound(p, "rs", 0, box);
    parse_bound(p, "ld", 1, box);
    parse_bound(p, "lq", 2, box);
    parse_bound(p, "psi", 3, box);
    const pmsm::FitnessWeights weights{p.real("w1"), p.real("w2"), p.real("w3"), p.real("w4")};
    const auto evaluation =
        p.text("fitness") == "direct" ? pmsm::FitnessEvaluation::direct : pmsm::FitnessEvaluation::expanded;

    if (p.has("data")) {
        std::string clash;
        for (const char* key :
             {"speed", "load", "noise_i", "noise_u", "seed", "n", "deadtime", "delay", "adc_bits", "hold"})
            if (p.given(key))
                clash += (clash.empty() ? "" : ", ") + std::string(key);
        if (!clash.empty())
            throw std::invalid_argument("pmsm: 'data' reads a dataset; the simulator parameters (" + clash +
                                        ") cannot be given with it");
        pmsm::DatasetReadOptions options;
        options.injection_threshold = p.real("id_threshold");
        DataFile file{p.text("data"), ""};
        auto problem = std::make_unique<pmsm::SteadyStateProblem>(
            pmsm::read_dataset_csv(file.path, options, &file.sha256), weights, std::move(box), evaluation);
        problem->set_data_files({std::move(file)});
        return problem;
    }
    pmsm::SimulatorConfig config;
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
    return std::make_unique<pmsm::SteadyStateProblem>(pmsm::simulate_dataset(config), weights, std::move(box),
                                                      evaluation);
}

} // namespace

void register_pmsm(ProblemRegistry& registry) {
    registry.add(
        {"pmsm",
         "PMSM identification of Rs, Ld, Lq, psi from steady-state dq data (eq. 11); f* = exact least "
         "squares",
         "Li, Wang and Ji (2017), PMSM parameter identification based on improved TLBO",
         {ParameterInfo::text(
              "data", "", "dataset CSV (t,ud,uq,id,iq,omega[,injected]); if absent the drive is simulated"),
          ParameterInfo::real("speed", 2500.0, 0.0, 20000.0,
                              "simulated speed reference, rpm (paper: 2500, 2000)")
              .open_below(),
          ParameterInfo::real("load", 2.0, -4.0, 4.0,
                              "simulated load torque, N m (paper: 2, 3; |load| < Kt iq_max = 4.19)"),
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
          ParameterInfo::text("rs", "0:0.5", "search bounds of Rs, ohm, lo:hi (paper: 0:0.5)"),
          ParameterInfo::text("ld", "0:0.01", "search bounds of Ld, H, lo:hi (paper: 0:0.01)"),
          ParameterInfo::text("lq", "0:0.01", "search bounds of Lq, H, lo:hi (paper: 0:0.01)"),
          ParameterInfo::text("psi", "0:0.1", "search bounds of psi, Wb, lo:hi (paper: 0:0.1)")},
         make_pmsm});
}

} // namespace mhb
