#include "algorithms/population_limits.hpp"

#include <cstdio>
#include <unistd.h>

namespace mhb {
namespace {

double physical_memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long page_size = ::sysconf(_SC_PAGESIZE);
    return pages > 0 && page_size > 0 ? static_cast<double>(pages) * static_cast<double>(page_size) : 0.0;
}

std::string gigabytes(double bytes) {
    char text[32];
    // 3 significant digits, without an exponent below 10^6 GB.
    const double gb = bytes / 1e9;
    std::snprintf(text, sizeof text, gb < 1000.0 ? "%.3g GB" : "%.0f GB", gb);
    return text;
}

} // namespace

std::optional<std::string> population_memory_refusal(const std::string& algorithm, double points,
                                                     Eigen::Index dimension, const std::string& parameter) {
    const double needed = points * static_cast<double>(dimension) * static_cast<double>(sizeof(double));
    const double available = physical_memory_bytes();
    if (available <= 0.0 || needed <= available)
        return std::nullopt;
    return algorithm + ": its population at D = " + std::to_string(dimension) + " needs " +
           gigabytes(needed) + " for its points alone, more than this machine's " + gigabytes(available) +
           " of memory; lower '" + parameter + "'";
}

std::optional<std::string> shade_population_refusal(const std::string& algorithm, const std::string& formula,
                                                    std::size_t n_init, long long n_min, double r_arc,
                                                    Eigen::Index dimension, const std::string& hint) {
    if (n_init < static_cast<std::size_t>(n_min))
        return algorithm + ": initial population " + formula + " = " + std::to_string(n_init) +
               " at D = " + std::to_string(dimension) + " is smaller than n_min = " + std::to_string(n_min) +
               "; raise 'r_ninit'" + (hint.empty() ? "" : " (" + hint + ")");
    return population_memory_refusal(algorithm, static_cast<double>(n_init) * (2.0 + r_arc), dimension,
                                     "r_ninit");
}

} // namespace mhb
