#include "problems/pmsm/dataset_csv.hpp"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "problems/core/csv_fields.hpp"
#include "problems/core/parameters.hpp"
#include "problems/core/sha256.hpp"
#include "problems/core/text_excerpt.hpp"

namespace mhb::pmsm {
namespace {

// Column order of the rows as stored in Dataset; `injected` is the optional seventh.
constexpr std::array<std::string_view, 7> column_names = {"t", "ud", "uq", "id", "iq", "omega", "injected"};
constexpr std::size_t injected_column = 6;
static_assert(max_dataset_magnitude == 1e9, "the messages below say [-1e9, 1e9]");

std::string column_label(std::string_view name) {
    return "column '" + std::string(name) + "'";
}

// A finite number within +-max_dataset_magnitude, or a one-line reason why not.
double parse_cell(std::string_view text, std::size_t line, std::string_view column, const CsvErrors& ctx) {
    double v = 0;
    if (parse_real(text, v)) {
        if (std::fabs(v) > max_dataset_magnitude)
            ctx.fail(line, column_label(column) + ": " + value_excerpt(text) + " is outside [-1e9, 1e9] (" +
                               "the range of a dataset value; larger ones would overflow the fit)");
        return v;
    }
    // from_chars reads "nan" and "inf"; name them as what they are.
    double raw = 0;
    std::string_view body = (!text.empty() && text.front() == '+') ? text.substr(1) : text;
    const auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), raw);
    if (ec == std::errc() && ptr == body.data() + body.size() && !std::isfinite(raw))
        ctx.fail(line,
                 column_label(column) + ": " + quoted_excerpt(text) + " is not finite (NaN or infinity)");
    if (text.empty())
        ctx.fail(line, column_label(column) + ": the field is empty");
    // Beyond a double's range (1e400) from_chars fails too: say what the limit is.
    if (ec == std::errc::result_out_of_range && ptr == body.data() + body.size())
        ctx.fail(line, column_label(column) + ": " + value_excerpt(text) + " is outside [-1e9, 1e9] (" +
                           "the range of a dataset value; larger ones would overflow the fit)");
    ctx.fail(line, column_label(column) + ": " + quoted_excerpt(text) + " is not a number");
}

} // namespace

Dataset read_dataset_csv(std::istream& in, const std::string& source, const DatasetReadOptions& options) {
    const CsvErrors ctx(source);
    Dataset data;
    std::string line;
    std::size_t line_number = 0;
    // position in the file's columns -> index into column_names
    std::vector<std::size_t> layout;
    bool has_injected = false;
    std::size_t header_line = 0;

    while (std::getline(in, line)) {
        ++line_number;
        std::string_view text = trim_csv_field(line);
        if (line_number == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") // a UTF-8 byte-order mark
            text = trim_csv_field(text.substr(3));
        if (text.empty())
            continue;
        if (text.front() == '#') {
            if (header_line != 0)
                ctx.fail(line_number, "metadata line after the header");
            const std::string_view body = trim_csv_field(text.substr(1));
            const auto eq = body.find('=');
            if (eq == std::string_view::npos)
                continue; // a plain comment
            const std::string key(trim_csv_field(body.substr(0, eq)));
            if (key.empty())
                ctx.fail(line_number, "metadata line " + quoted_excerpt(text) + " has an empty key");
            if (data.find_metadata(key) != nullptr)
                ctx.fail(line_number, "metadata key " + quoted_excerpt(key) + " is given twice");
            data.metadata.emplace_back(key, std::string(trim_csv_field(body.substr(eq + 1))));
            continue;
        }
        const auto fields = split_csv_fields(text);
        if (header_line == 0) {
            header_line = line_number;
            std::array<bool, column_names.size()> seen{};
            for (std::size_t position = 0; position < fields.size(); ++position) {
                const std::string_view name = fields[position];
                std::size_t found = column_names.size();
                for (std::size_t c = 0; c < column_names.size(); ++c)
                    if (column_names[c] == name)
                        found = c;
                if (found == column_names.size())
                    ctx.fail(line_number, "column " + std::to_string(position + 1) + ": unknown column " +
                                              quoted_excerpt(name) +
                                              " (expected t,ud,uq,id,iq,omega[,injected])");
                if (seen[found])
                    ctx.fail(line_number, "column " + std::to_string(position + 1) + ": column " +
                                              quoted_excerpt(name) + " appears twice");
                seen[found] = true;
                layout.push_back(found);
            }
            for (std::size_t c = 0; c < injected_column; ++c)
                if (!seen[c])
                    ctx.fail(line_number,
                             "column '" + std::string(column_names[c]) +
                                 "' is missing from the header (expected t,ud,uq,id,iq,omega[,injected])");
            has_injected = seen[injected_column];
            continue;
        }
        if (fields.size() != layout.size())
            ctx.fail(line_number, "row has " + std::to_string(fields.size()) + " fields but the header has " +
                                      std::to_string(layout.size()) + " columns");
        std::array<double, column_names.size()> row{};
        for (std::size_t position = 0; position < fields.size(); ++position) {
            const std::size_t c = layout[position];
            if (c == injected_column) {
                if (fields[position] != "0" && fields[position] != "1")
                    ctx.fail(line_number, column_label("injected") + ": " + quoted_excerpt(fields[position]) +
                                              " is not 0 or 1");
                row[c] = fields[position] == "1" ? 1.0 : 0.0;
            } else {
                row[c] = parse_cell(fields[position], line_number, column_names[c], ctx);
            }
        }
        const bool injected =
            has_injected ? row[injected_column] != 0.0 : std::fabs(row[3]) > options.injection_threshold;
        data.push_back(row[0], row[1], row[2], row[3], row[4], row[5], injected);
    }
    if (in.bad())
        ctx.fail_file(std::string("read error (") + std::strerror(errno) + ")");
    if (header_line == 0)
        ctx.fail_file("no header line (expected t,ud,uq,id,iq,omega[,injected])");
    if (data.size() < options.min_rows)
        ctx.fail(line_number, "too few rows: " + std::to_string(data.size()) + " data rows, at least " +
                                  std::to_string(options.min_rows) + " needed");
    const auto [off, on] = data.state_counts();
    const std::string how = has_injected ? "by its 'injected' column"
                                         : "by |id| > " + format_real(options.injection_threshold) + " A";
    if (off == 0 && options.require_both_states)
        ctx.fail(line_number, column_label(has_injected ? "injected" : "id") +
                                  ": no samples in the id = 0 state (" + how + ")");
    if (on == 0 && options.require_both_states)
        ctx.fail(line_number, column_label(has_injected ? "injected" : "id") +
                                  ": no samples in the injected state (" + how + ")");
    return data;
}

Dataset read_dataset_csv(const std::string& path, const DatasetReadOptions& options, std::string* sha256) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw std::runtime_error(path + ": is a directory, not a dataset file");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path + ": cannot open the dataset file (" +
                                 (errno != 0 ? std::strerror(errno) : "unknown reason") + ")");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad())
        throw std::runtime_error(path + ": reading the dataset file failed");
    const std::string content = std::move(bytes).str();
    if (sha256 != nullptr)
        *sha256 = sha256_hex(content);
    std::istringstream parsed(content);
    return read_dataset_csv(parsed, path, options);
}

void write_dataset_csv(std::ostream& out, const Dataset& data) {
    for (const auto& [key, value] : data.metadata)
        out << "# " << key << '=' << value << '\n';
    out << "t,ud,uq,id,iq,omega,injected\n";
    for (std::size_t k = 0; k < data.size(); ++k)
        out << format_real(data.t[k]) << ',' << format_real(data.ud[k]) << ',' << format_real(data.uq[k])
            << ',' << format_real(data.id[k]) << ',' << format_real(data.iq[k]) << ','
            << format_real(data.omega[k]) << ',' << (data.injected[k] ? '1' : '0') << '\n';
}

void write_dataset_csv(const std::string& path, const Dataset& data) {
    errno = 0;
    std::ofstream out(path);
    if (!out)
        throw std::runtime_error(path + ": cannot open for writing (" +
                                 (errno != 0 ? std::strerror(errno) : "unknown reason") + ")");
    write_dataset_csv(out, data);
    out.flush();
    if (!out)
        throw std::runtime_error(path + ": write failed (" +
                                 (errno != 0 ? std::strerror(errno) : "unknown reason") + ")");
}

} // namespace mhb::pmsm
