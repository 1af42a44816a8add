// How the report's console lines count things: "1 run", "3 runs".
#pragma once

#include <cstddef>
#include <string>

namespace mhb {

inline std::string count_of(std::size_t n, const char* noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

} // namespace mhb
