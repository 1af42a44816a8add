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

#include "problems/parameters.hpp"
#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/drive_simulator.hpp"
#include "problems/text_excerpt.hpp"
#include "results/csv.hpp"
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
    const std::string& text = vm[name].as<std::string>();
    long long v = 0;
    if (!parse_integer(text, v))
        throw std::invalid_argument(std::string("--") + name + " = " + value_excerpt(text) + " " +
                                    integer_refusal(text, min, max));
    if (v < min || v > max)
        throw std::invalid_argument(std::string("--") + name + " = " + value_excerpt(text) + " is outside [" +
                                    std::to_string(min) + ", " + std::to_string(max) + "]");
    return v;
}

} // namespace

int run_simulate_command(const std::vector<std::string>& args) {
    pmsm::SimulatorConfig config;
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
    const auto text = [] { return po::value<std::string>(); };
    // clang-format off
    options.add_options()
        ("help,h", "this text")
        ("out,o", po::value<std::string>(&out), "dataset CSV to write ('-' for standard output); required")
        ("speed", text()->default_value("2500"), "speed reference, rpm (paper: 2500 and 2000)")
        ("load", text()->default_value("2"),
         "load torque, N m (paper: 2 and 3; |load| must stay below Kt * 18 A = 4.19 N m)")
        ("noise-i", text()->default_value("0"),
         "standard deviation of Gaussian noise on the measured id and iq, A (inside the loop)")
        ("noise-u", text()->default_value("0"),
         "standard deviation of Gaussian noise on the logged ud and uq, V (the motor gets the clean "
         "voltage)")
        ("seed", text()->default_value("1"), "seed of the noise streams (integer >= 0)")
        ("samples", text()->default_value("300"),
         "samples per injection state, 1..500 (one 50 ms plateau holds 500)")
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
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { std::cout << options << '\n'; }))
        return exit_ok;
    if (out.empty())
        throw std::invalid_argument("--out FILE is required (see mhbench simulate --help)");
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

    const pmsm::Dataset data = pmsm::simulate_dataset(config);
    if (out == "-") {
        pmsm::write_dataset_csv(std::cout, data);
    } else {
        // Written whole or not at all: a failed write leaves neither a partial file nor a .tmp.
        std::ostringstream text_out;
        pmsm::write_dataset_csv(text_out, data);
        write_file_atomically(out, text_out.str());
        std::cerr << "mhbench simulate: wrote " << data.size() << " samples (" << config.samples_per_state
                  << " per state) to " << out << '\n';
    }
    return exit_ok;
}

} // namespace mhb::cli
