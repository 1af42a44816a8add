// `mhbench simulate`: runs the built-in drive simulator of the paper's motor (problems/pmsm/
// drive_simulator.hpp) at one operating condition and writes the steady-state dataset CSV that
// `pmsm:data=FILE` and `mhbench identify` read.
#include <boost/program_options.hpp>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/drive_simulator.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"

namespace mhb::cli {

namespace po = boost::program_options;

int run_simulate_command(const std::vector<std::string>& args) {
    pmsm::SimulatorConfig config;
    long long seed = 1;
    std::string out;
    po::options_description options(
        "mhbench simulate: simulate the paper's PMSM drive (Li, Wang and Ji 2017, Table 1 motor: Rs 0.33 "
        "ohm,\n"
        "Ld = Lq = 3.24 mH, psi 0.0776 Wb, p = 2) under speed and current PI control at Ts = 100 us, with a\n"
        "-2 A d-axis injection alternating every 50 ms after 0.2 s of settling, and write the last N "
        "samples\n"
        "of an id = 0 plateau and of the following injected plateau as a dataset CSV\n"
        "(# key=value metadata, then t,ud,uq,id,iq,omega,injected in s, V, V, A, A, electrical rad/s).\n\n"
        "Usage: mhbench simulate --out FILE [options]\n\nOptions");
    // clang-format off
    options.add_options()
        ("help,h", "this text")
        ("out,o", po::value<std::string>(&out), "dataset CSV to write ('-' for standard output); required")
        ("speed", po::value<double>(&config.condition.speed_rpm)->default_value(2500.0),
         "speed reference, rpm (paper: 2500 and 2000)")
        ("load", po::value<double>(&config.condition.load_Nm)->default_value(2.0),
         "load torque, N m (paper: 2 and 3; |load| must stay below Kt * 18 A = 4.19 N m)")
        ("noise-i", po::value<double>(&config.noise_i)->default_value(0.0),
         "standard deviation of Gaussian noise on the measured id and iq, A (inside the loop)")
        ("noise-u", po::value<double>(&config.noise_u)->default_value(0.0),
         "standard deviation of Gaussian noise on the logged ud and uq, V (the motor gets the clean "
         "voltage)")
        ("seed", po::value<long long>(&seed)->default_value(1), "seed of the noise streams (integer >= 0)")
        ("samples", po::value<int>(&config.samples_per_state)->default_value(300),
         "samples per injection state, 1..500 (one 50 ms plateau holds 500)")
        ("adc-bits", po::value<int>(&config.adc_bits)->default_value(0),
         "quantise the phase currents with an ADC of this many bits over +-20 A (0: off)")
        ("deadtime", po::value<double>(&config.dead_time)->default_value(0.0),
         "inverter dead time, s (0: ideal average inverter; 1e-6 already shifts uq by ~7 V)")
        ("delay", po::value<int>(&config.delay_periods)->default_value(0),
         "computation delay, control periods (0 or 1)")
        ("stator-hold", po::bool_switch(&config.stator_frame_hold),
         "hold the voltage in the stator frame, as a real inverter does, without angle compensation: the\n"
         "vector lags the rotor by omega Ts / 2 on average (1.5 omega Ts with --delay 1), about 1.1 V on ud\n"
         "at 2500 rpm; default: held in the rotor dq frame (ideal)");
    // clang-format on
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { std::cout << options << '\n'; }))
        return exit_ok;
    if (out.empty())
        throw std::invalid_argument("--out FILE is required (see mhbench simulate --help)");
    if (seed < 0)
        throw std::invalid_argument("--seed must be >= 0, got " + std::to_string(seed));
    config.seed = static_cast<std::uint64_t>(seed);

    const pmsm::Dataset data = pmsm::simulate_dataset(config);
    if (out == "-") {
        pmsm::write_dataset_csv(std::cout, data);
    } else {
        pmsm::write_dataset_csv(out, data);
        std::cerr << "mhbench simulate: wrote " << data.size() << " samples (" << config.samples_per_state
                  << " per state) to " << out << '\n';
    }
    return exit_ok;
}

} // namespace mhb::cli
