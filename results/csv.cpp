#include "results/csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mhb {

std::string csv_field(std::string_view text) {
    const bool needs_quotes = text.find_first_of(",\"\n\r") != std::string_view::npos;
    if (!needs_quotes)
        return std::string(text);
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"')
            out += "\"\"";
        else if (c == '\n' || c == '\r')
            out += ' ';
        else
            out += c;
    }
    return out + '"';
}

std::string csv_number(double value) {
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    char buf[64];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, result.ptr);
}

std::string csv_number(std::int64_t value) {
    return std::to_string(value);
}

std::string csv_optional(const std::optional<double>& value) {
    return value ? csv_number(*value) : "";
}

std::vector<std::string> csv_split(std::string_view line) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.push_back(std::move(field));
            field.clear();
        } else if (c != '\r') {
            field += c;
        }
    }
    if (quoted)
        throw std::runtime_error("unterminated quoted field");
    fields.push_back(std::move(field));
    return fields;
}

std::size_t CsvTable::column(std::string_view name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == name)
            return i;
    throw std::runtime_error(path.string() + ": column '" + std::string(name) + "' is missing");
}

bool CsvTable::has_column(std::string_view name) const {
    for (const auto& h : header)
        if (h == name)
            return true;
    return false;
}

namespace {

[[noreturn]] void bad_cell(const CsvTable& t, std::size_t row, std::size_t column, const char* what) {
    throw std::runtime_error(t.path.string() + ", line " + std::to_string(t.line_numbers[row]) +
                             ", column '" + t.header[column] + "': '" + t.rows[row][column] + "' is not " +
                             what);
}

} // namespace

double CsvTable::number(std::size_t row, std::size_t column) const {
    const std::string& text = rows[row][column];
    if (text == "nan")
        return std::nan("");
    if (text == "inf")
        return INFINITY;
    if (text == "-inf")
        return -INFINITY;
    double value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end)
        bad_cell(*this, row, column, "a number");
    return value;
}

std::optional<double> CsvTable::optional_number(std::size_t row, std::size_t column) const {
    if (rows[row][column].empty())
        return std::nullopt;
    return number(row, column);
}

std::int64_t CsvTable::integer(std::size_t row, std::size_t column) const {
    const std::string& text = rows[row][column];
    std::int64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end)
        bad_cell(*this, row, column, "an integer");
    return value;
}

CsvTable read_csv(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path.string() + ": cannot be opened (missing?)");
    CsvTable table;
    table.path = path;
    std::string line;
    std::size_t line_number = 0;
    bool complete_last_line = true;
    while (std::getline(in, line)) {
        ++line_number;
        complete_last_line = !in.eof();
        if (line.empty() || line[0] == '#')
            continue;
        std::vector<std::string> fields;
        try {
            fields = csv_split(line);
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(path.string() + ", line " + std::to_string(line_number) + ": " +
                                     e.what());
        }
        if (table.header.empty()) {
            table.header = std::move(fields);
            continue;
        }
        if (fields.size() != table.header.size())
            throw std::runtime_error(path.string() + ", line " + std::to_string(line_number) + ": expected " +
                                     std::to_string(table.header.size()) + " fields, found " +
                                     std::to_string(fields.size()) + " (truncated or damaged file?)");
        table.rows.push_back(std::move(fields));
        table.line_numbers.push_back(line_number);
    }
    if (table.header.empty())
        throw std::runtime_error(path.string() + ": is empty (no header line)");
    if (!complete_last_line)
        throw std::runtime_error(path.string() + ", line " + std::to_string(line_number) +
                                 ": the file ends in the middle of a line (truncated?)");
    return table;
}

std::string read_whole_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path.string() + ": cannot be opened (missing?)");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
    std::filesystem::path temporary = path;
    temporary += ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
            throw std::runtime_error(temporary.string() + ": cannot be written");
        out.write(content.data(), static_cast<std::streamsize>(content.size()));
        out.flush();
        if (!out)
            throw std::runtime_error(temporary.string() + ": writing failed (disk full?)");
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec)
        throw std::runtime_error(path.string() + ": cannot be written (" + ec.message() + ")");
}

} // namespace mhb
