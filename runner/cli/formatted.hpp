// printf-style formatting of up to three numbers, for the fixed-width reports of `mhbench identify`
// (their columns are printf widths; iostream manipulators would be longer and no clearer).
#pragma once

#include <cstdio>
#include <string>

namespace mhb::cli {

inline std::string formatted(const char* format, double a, double b = 0, double c = 0) {
    char buf[240];
    std::snprintf(buf, sizeof buf, format, a, b, c);
    return buf;
}

} // namespace mhb::cli
