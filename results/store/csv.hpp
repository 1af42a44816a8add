// Minimal CSV for the files mhbench itself writes and reads (RFC 4180 quoting, one record per
// line). User datasets have their own validating reader (problems/pmsm/).
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mhb {

// Quotes a field if it holds ',', '"' or a line break; line breaks become spaces.
std::string csv_field(std::string_view text);
// The shortest text that reads back to the same double; "nan", "inf", "-inf" otherwise.
std::string csv_number(double value);
std::string csv_number(std::int64_t value);
std::string csv_optional(const std::optional<double>& value);
// Splits one line into fields, undoing csv_field's quoting. Throws std::runtime_error on an
// unterminated quote.
std::vector<std::string> csv_split(std::string_view line);

struct CsvTable {
    std::filesystem::path path;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows; // every row has header.size() fields
    std::vector<std::size_t> line_numbers;      // 1-based line of each row in the file

    // Index of a column; throws std::runtime_error naming the file and the missing column.
    [[nodiscard]] std::size_t column(std::string_view name) const;
    [[nodiscard]] bool has_column(std::string_view name) const;
    // Typed access with file/row/column in the error on bad text.
    [[nodiscard]] double number(std::size_t row, std::size_t column) const;
    [[nodiscard]] std::optional<double> optional_number(std::size_t row, std::size_t column) const;
    [[nodiscard]] std::int64_t integer(std::size_t row, std::size_t column) const;
};

// Reads a whole CSV file written by mhbench. Throws std::runtime_error with the file and line
// when it is missing, empty, or a row has the wrong number of fields (e.g. a truncated file).
CsvTable read_csv(const std::filesystem::path& path);
// The same from text already read (`path` names it in errors).
CsvTable parse_csv(std::istream& in, const std::filesystem::path& path);

// The whole content of a file; throws std::runtime_error naming it when it cannot be opened.
std::string read_whole_file(const std::filesystem::path& path);

// Writes `content` to `path` atomically and durably: a temporary file in the same folder, synced,
// renamed over `path`, and the folder synced. On an error the temporary file is removed.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

} // namespace mhb
