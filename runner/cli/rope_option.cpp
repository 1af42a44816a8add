#include "runner/cli/rope_option.hpp"

#include <cmath>

namespace mhb::cli {

void set_rope_options(const boost::program_options::variables_map& vm, ReportOptions& options) {
    if (vm.count("rope") != 0)
        options.rope = vm["rope"].as<double>();
    if (vm.count("raw-rope") != 0)
        options.raw_rope = vm["raw-rope"].as<double>();
}

std::optional<std::string> rope_option_error(const boost::program_options::variables_map& vm) {
    for (const char* name : {"rope", "raw-rope"}) {
        if (vm.count(name) == 0)
            continue;
        const double value = vm[name].as<double>();
        if (!(value >= 0.0) || !std::isfinite(value))
            return std::string(name) + " = " +
                   (std::isnan(value) ? std::string("nan") : format_number(value)) + " is outside [0, inf)";
    }
    return std::nullopt;
}

} // namespace mhb::cli
