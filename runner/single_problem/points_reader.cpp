#include "runner/single_problem/points_reader.hpp"

#include <cerrno>
#include <cstring>
#include <istream>
#include <stdexcept>

#include "problems/core/parameters.hpp"
#include "problems/core/text_excerpt.hpp"

namespace mhb {

std::vector<PointLine> read_points(std::istream& in, const std::string& source, Eigen::Index dimension) {
    std::vector<PointLine> points;
    std::string text;
    std::size_t line = 0;
    while (std::getline(in, text)) {
        ++line;
        if (!text.empty() && text.back() == '\r')
            text.pop_back();
        if (line == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) // a UTF-8 byte-order mark
            text.erase(0, 3);
        const auto first = text.find_first_not_of(" \t,");
        if (first == std::string::npos || text[first] == '#')
            continue;
        const std::string where = source + ", line " + std::to_string(line);
        std::vector<double> values;
        std::size_t i = 0;
        while (i < text.size()) {
            while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == ','))
                ++i;
            if (i >= text.size())
                break;
            std::size_t j = i;
            while (j < text.size() && text[j] != ' ' && text[j] != '\t' && text[j] != ',')
                ++j;
            const std::string token = text.substr(i, j - i);
            double v = 0.0;
            if (!parse_real(token, v))
                throw std::runtime_error(where + ", column " + std::to_string(i + 1) + " (coordinate " +
                                         std::to_string(values.size() + 1) + "): " + quoted_excerpt(token) +
                                         " is not a finite number");
            values.push_back(v);
            i = j;
        }
        if (static_cast<Eigen::Index>(values.size()) != dimension)
            throw std::runtime_error(where + ": " + std::to_string(values.size()) +
                                     " coordinates, but the problem has " + std::to_string(dimension) +
                                     " dimensions");
        PointLine p;
        p.line = line;
        p.x = Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
        points.push_back(std::move(p));
    }
    if (in.bad()) // e.g. a directory: it opens, but reading it fails
        throw std::runtime_error(source + ": cannot be read (" + std::strerror(errno) + ")");
    // Printing nothing and exiting 0 would let a pipeline that produced no point pass unnoticed.
    if (points.empty())
        throw std::runtime_error(source + ": holds no point (one a line, " + std::to_string(dimension) +
                                 " coordinates separated by spaces or commas)");
    return points;
}

} // namespace mhb
