// The points file of `mhbench eval`: one point a line, coordinates separated by spaces, tabs or
// commas; blank lines and lines starting with '#' are skipped.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace mhb {

struct PointLine {
    std::size_t line = 0; // 1-based line of the point in its file
    Eigen::VectorXd x;
};

// Every point of `in`, each with `dimension` finite coordinates. Any bad text is a
// std::runtime_error naming `source`, the line and the column.
std::vector<PointLine> read_points(std::istream& in, const std::string& source, Eigen::Index dimension);

} // namespace mhb
