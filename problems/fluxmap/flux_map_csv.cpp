// The flux-map CSV reader (flux_map.hpp): one clear line per defect, naming file, line, column.
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "problems/core/csv_fields.hpp"
#include "problems/core/parameters.hpp"
#include "problems/core/sha256.hpp"
#include "problems/core/text_excerpt.hpp"
#include "problems/fluxmap/flux_map.hpp"

namespace mhb::fluxmap {
namespace {

constexpr std::array<std::string_view, 4> column_names = {"i_d", "i_q", "psi_d", "psi_q"};

// "nan", "inf", "infinity" in any case, with an optional sign: what strtod reads as non-finite.
bool names_non_finite(std::string_view text) {
    if (!text.empty() && (text.front() == '+' || text.front() == '-'))
        text.remove_prefix(1);
    std::string lower(text);
    for (char& ch : lower)
        ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return lower == "nan" || lower == "inf" || lower == "infinity";
}

// A number too large for a double (1e400): refused for its range, not as "not a number".
bool beyond_double(std::string_view text) {
    const std::string copy(text);
    char* end = nullptr;
    const double v = std::strtod(copy.c_str(), &end);
    return end == copy.c_str() + copy.size() && std::isinf(v);
}

class Reader : public CsvErrors {
public:
    using CsvErrors::CsvErrors;

    // The header's column index of each of the four names.
    std::array<std::size_t, 4> header(std::string_view line) const {
        const auto fields = split_csv_fields(line);
        std::array<std::size_t, 4> index{};
        for (std::size_t c = 0; c < column_names.size(); ++c) {
            std::size_t found = fields.size();
            for (std::size_t k = 0; k < fields.size(); ++k)
                if (fields[k] == column_names[c])
                    found = k;
            if (found == fields.size())
                fail(1, "the header has no column '" + std::string(column_names[c]) +
                            "' (a flux map has the columns i_d,i_q,psi_d,psi_q)");
            index[c] = found;
        }
        return index;
    }

    double cell(std::string_view text, std::size_t line, std::size_t column) const {
        const std::string label = "column '" + std::string(column_names[column]) + "': ";
        if (text.empty())
            fail(line, label + "the field is empty");
        double v = 0;
        const bool number = parse_real(text, v);
        if (!number && names_non_finite(text))
            fail(line, label + quoted_excerpt(text) + " is not finite (NaN or infinity)");
        if (!number && !beyond_double(text))
            fail(line, label + quoted_excerpt(text) + " is not a number");
        const bool current = column < 2;
        const double limit = current ? max_current : max_flux;
        if (!number || std::fabs(v) > limit)
            fail(line,
                 label + value_excerpt(text) +
                     (current ? " is outside [-1e5, 1e5] A (a machine's current; larger is damage or mA)"
                              : " is outside [-100, 100] V s (a machine's flux linkage; larger is damage "
                                "or mV s)"));
        return v;
    }
};

} // namespace

FluxMap read_flux_map_csv(std::istream& in, const std::string& source, Eigen::Index min_points) {
    const Reader reader(source);
    std::string line;
    if (!std::getline(in, line))
        reader.fail_file(
            "the file is empty (a flux map has the header i_d,i_q,psi_d,psi_q and one row per point)");
    if (line.rfind("\xEF\xBB\xBF", 0) == 0)
        line.erase(0, 3);
    const auto index = reader.header(line);
    std::vector<std::array<double, 4>> rows;
    std::set<std::pair<double, double>> seen; // (psi_d, psi_q): the model's abscissa
    for (std::size_t number = 2; std::getline(in, line); ++number) {
        if (trim_csv_field(line).empty())
            continue;
        const auto fields = split_csv_fields(line);
        std::array<double, 4> row{};
        for (std::size_t c = 0; c < 4; ++c) {
            if (index[c] >= fields.size())
                reader.fail(number, "column '" + std::string(column_names[c]) + "' is missing (the row has " +
                                        std::to_string(fields.size()) + " fields)");
            row[c] = reader.cell(fields[index[c]], number, c);
        }
        if (row[2] == 0.0 && row[3] == 0.0)
            reader.fail(number, "columns 'psi_d', 'psi_q': both are 0 (the model's powers of |psi| need a "
                                "nonzero flux linkage; zero flux carries no information)");
        if (!seen.emplace(row[2], row[3]).second)
            reader.fail(number, "columns 'psi_d', 'psi_q': the point (" + format_real(row[2]) + ", " +
                                    format_real(row[3]) + ") is given twice (a duplicate point)");
        rows.push_back(row);
    }
    if (static_cast<Eigen::Index>(rows.size()) < min_points)
        reader.fail_file("has " + std::to_string(rows.size()) + (rows.size() == 1 ? " point" : " points") +
                         ", fewer than the model's " + std::to_string(min_points) + " parameters");
    FluxMap map;
    const auto n = static_cast<Eigen::Index>(rows.size());
    map.i_d.resize(n), map.i_q.resize(n), map.psi_d.resize(n), map.psi_q.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
        const auto& r = rows[static_cast<std::size_t>(k)];
        map.i_d[k] = r[0], map.i_q[k] = r[1], map.psi_d[k] = r[2], map.psi_q[k] = r[3];
    }
    return map;
}

FluxMap read_flux_map_csv(const std::string& path, Eigen::Index min_points, std::string* sha256) {
    // A directory opens as a stream that reads nothing: say what it is rather than "no header".
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw std::runtime_error(path + ": cannot be read (" + std::strerror(EISDIR) + ")");
    std::ifstream file(path, std::ios::binary);
    if (!file)
        throw std::runtime_error(path + ": cannot be opened (" + std::strerror(errno) + ")");
    std::ostringstream bytes;
    bytes << file.rdbuf();
    const std::string text = bytes.str();
    if (sha256)
        *sha256 = sha256_hex(text);
    std::istringstream in(text);
    return read_flux_map_csv(in, path, min_points);
}

} // namespace mhb::fluxmap
