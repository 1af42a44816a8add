// `mhbench simulate`: runs the built-in drive simulator of the paper's motor (problems/pmsm/
// drive_simulator.hpp) at one operating condition and writes the steady-state dataset CSV that
// `pmsm:data=FILE` and `mhbench identify` read.
#include <boost/program_options.hpp>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/core/text_excerpt.hpp"
#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/drive_simulator.hpp"
#include "results/store/csv.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"

namespace mhb::cli {

namespace po = boost::program_options;

namespace {

// The numeric options are read as text and checked here, so that a bad value gets one line that
// quotes it (cut to 40 characters) and, for an integer too large, names the largest allowed.
double real_option(const po::variables_map& vm, const char* name) {
    const std::string& text = vm[name].as<std::string>();
    double v = 0;
    if (!parse_real(text, v))
        throw std::invalid_argument(std::string("--") + name + " = " + value_excerpt(text) +
                                    " is not a finite number");
    return v;
}

long long integer_option(const po::variables_map& vm, const char* name, long long min, long long max) {
    return integer_argument(vm[name].as<std::string>(), name, min, max);
}

// The options; `config.stator_frame_hold` and `out` are written by Boost as it parses.
po::options_description simulate_options(pmsm::SimulatorConfig& config, std::string& out) {
    po::options_description options(
        "mhbench simulate: simulate a PMSM drive - the paper's motor by default (Li, Wang and Ji 2017,\n"
        "Table 1: Rs 0.33 ohm, Ld = Lq = 3.24 mH, psi 0.0776 Wb, p = 2), any motor with the motor options -\n"
        "under speed and current PI control at Ts = 100 us, with a d-axis current injection alternating\n"
        "every 50 ms after 0.2 s of settling, and write a dataset CSV (# key=value metadata, then\n"
        "t,ud,uq,id,iq,omega,injected in s, V, V, A, A, electrical rad/s). --window steady keeps the last N\n"
        "samples of an id = 0 plateau and of the following injected plateau (for model=steady);\n"
        "--window transient keeps the 2N consecutive samples around the step between them (for\n"
        "model=dynamic and model=output).\n\n"
        "Usage: mhbench simulate --out FILE [options]\n\nOptions");
    const auto text = [] { return po::value<std::string>(); };
    // clang-format off
    options.add_options()
        ("help,h", "this text")
        ("out,o", po::value<std::string>(&out), "dataset CSV to write ('-' for standard output); required")
        ("motor", po::value<std::string>()->default_value("paper"),
         "the motor: paper (Table 1) or ipm (an interior-PM motor: 0.9 ohm, Ld 6 mH, Lq 14 mH, 0.17 Wb, p = 3,\n"
         "J 2e-4 kg m^2, B 1e-4 N m s/rad); the options below override its values")
        ("rs", text(), "stator resistance Rs, ohm")
        ("ld", text(), "d-axis inductance Ld, H")
        ("lq", text(), "q-axis inductance Lq, H")
        ("psi", text(), "permanent-magnet flux linkage psi, Wb")
        ("pole-pairs", text(), "pole pairs p")
        ("inertia", text(), "rotor inertia J, kg m^2")
        ("friction", text(), "viscous friction B, N m s/rad")
        ("vdc", text()->default_value("540"), "DC bus, V (the voltage vector is limited to Vdc / sqrt(3))")
        ("current-bandwidth", text()->default_value("3000"),
         "current-loop bandwidth wc, rad/s (PI gains Kp = wc L, Ki = wc Rs, from the motor's values)")
        ("speed-bandwidth", text()->default_value("800"),
         "speed-loop bandwidth ws, rad/s (Kp_w = ws J / Kt, Ki_w = Kp_w ws / 3); lower it for a large J")
        ("iq-max", text()->default_value("18"), "limit of the q-current reference, A")
        ("injection", text()->default_value("-2"), "the injected d-axis current, A")
        ("speed", text()->default_value("2500"), "speed reference, rpm (paper: 2500 and 2000)")
        ("load", text()->default_value("2"),
         "load torque, N m (paper: 2 and 3; |load| must stay below Kt * iq-max, 4.19 N m for the paper's motor)")
        ("window", po::value<std::string>()->default_value("steady"),
         "steady: the settled ends of two plateaus; transient: 2N consecutive samples around the step")
        ("noise-i", text()->default_value("0"),
         "standard deviation of Gaussian noise on the measured id and iq, A (inside the loop)")
        ("noise-u", text()->default_value("0"),
         "standard deviation of Gaussian noise on the logged ud and uq, V (the motor gets the clean "
         "voltage)")
        ("seed", text()->default_value("1"), "seed of the noise streams (integer >= 0)")
        ("samples", text()->default_value("300"),
         "samples per injection state N, 1..500 (one 50 ms plateau holds 500)")
        ("adc-bits", text()->default_value("0"),
         "quantise the phase currents with an ADC of this many bits over +-20 A (0: off)")
        ("deadtime", text()->default_value("0"),
         "inverter dead time, s (0: ideal average inverter; 1e-6 already shifts uq by ~7 V)")
        ("delay", text()->default_value("0"), "computation delay, control periods (0 or 1)")
        ("stator-hold", po::bool_switch(&config.stator_frame_hold),
         "hold the voltage in the stator frame, as a real inverter does, without angle compensation: the\n"
         "vector lags the rotor by omega Ts / 2 on average (1.5 omega Ts with --delay 1), about 1.1 V on ud\n"
         "at 2500 rpm; default: held in the rotor dq frame (ideal)");
    // clang-format on
    return options;
}

// --motor, then the motor options that override its values.
pmsm::MotorParameters motor_of(const po::variables_map& vm) {
    const std::string& motor = vm["motor"].as<std::string>();
    if (motor != "paper" && motor != "ipm")
        throw std::invalid_argument("--motor = " + value_excerpt(motor) + " is not one of paper, ipm");
    pmsm::MotorParameters parameters = motor == "ipm" ? pmsm::ipm_motor() : pmsm::paper_motor();
    const auto override_value = [&](const char* name, double& value) {
        if (vm.count(name) != 0)
            value = real_option(vm, name);
    };
    override_value("rs", parameters.Rs);
    override_value("ld", parameters.Ld);
    override_value("lq", parameters.Lq);
    override_value("psi", parameters.psi);
    override_value("inertia", parameters.J);
    override_value("friction", parameters.B);
    if (vm.count("pole-pairs") != 0)
        parameters.pole_pairs = static_cast<int>(integer_option(vm, "pole-pairs", 1, 100));
    return parameters;
}

// The drive, the condition and the measurement, from the options (the motor's already set).
void configure(const po::variables_map& vm, pmsm::SimulatorConfig& config) {
    config.vdc = real_option(vm, "vdc");
    config.current_bandwidth = real_option(vm, "current-bandwidth");
    config.speed_bandwidth = real_option(vm, "speed-bandwidth");
    config.iq_max = real_option(vm, "iq-max");
    config.injection_current = real_option(vm, "injection");
    const std::string& window = vm["window"].as<std::string>();
    if (window != "steady" && window != "transient")
        throw std::invalid_argument("--window = " + value_excerpt(window) +
                                    " is not one of steady, transient");
    config.window = window == "steady" ? pmsm::SimulatedWindow::steady : pmsm::SimulatedWindow::transient;
    config.condition.speed_rpm = real_option(vm, "speed");
    config.condition.load_Nm = real_option(vm, "load");
    config.noise_i = real_option(vm, "noise-i");
    config.noise_u = real_option(vm, "noise-u");
    config.dead_time = real_option(vm, "deadtime");
    // The simulator checks the ranges of the rest; these bounds only keep the integers in range.
    config.seed =
        static_cast<std::uint64_t>(integer_option(vm, "seed", 0, std::numeric_limits<long long>::max()));
    config.samples_per_state = static_cast<int>(integer_option(vm, "samples", 1, 500));
    config.adc_bits = static_cast<int>(integer_option(vm, "adc-bits", 0, 24));
    config.delay_periods = static_cast<int>(integer_option(vm, "delay", 0, 1));
}

} // namespace

int run_simulate_command(const std::vector<std::string>& args) {
    pmsm::SimulatorConfig config;
    std::string out;
    const po::options_description options = simulate_options(config, out);
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { std::cout << options << '\n'; }))
        return exit_ok;
    if (out.empty())
        throw std::invalid_argument("--out FILE is required (see mhbench simulate --help)");
    config.motor = motor_of(vm);
    configure(vm, config);

    const pmsm::Dataset data = pmsm::simulate_dataset(config);
    if (out == "-") {
        pmsm::write_dataset_csv(std::cout, data);
    } else {
        // Written whole or not at all: a failed write leaves neither a partial file nor a .tmp.
        std::ostringstream text_out;
        pmsm::write_dataset_csv(text_out, data);
        write_file_atomically(out, text_out.str());
        std::cerr << "mhbench simulate: wrote " << data.size() << " samples (" << config.samples_per_state
                  << " per state, " << pmsm::to_string(config.window) << " window) to " << out << '\n';
    }
    return exit_ok;
}

} // namespace mhb::cli
