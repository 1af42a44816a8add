// Fuzzes the points reader of `mhbench eval` (runner/single_problem/points_reader.hpp). The first byte gives
// the problem's dimension (a digit, e.g. "2\n1 2\n", or any byte modulo 16); the rest is the file.
#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "runner/single_problem/points_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0)
        return 0;
    const int first = data[0];
    const Eigen::Index dimension = first >= '0' && first <= '9' ? first - '0' : first % 16;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
    try {
        for (const auto& point : mhb::read_points(in, "points.txt", dimension))
            if (point.x.size() != dimension || !point.x.allFinite() || point.line == 0)
                std::abort(); // a point read must have the dimension asked for, finite coordinates
    } catch (const std::runtime_error&) {
    }
    return 0;
}
