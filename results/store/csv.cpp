#include "results/store/csv.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

#include "results/store/durable_file.hpp"

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
        return std::numeric_limits<double>::infinity();
    if (text == "-inf")
        return -std::numeric_limits<double>::infinity();
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
    return parse_csv(in, path);
}

CsvTable parse_csv(std::istream& in, const std::filesystem::path& path) {
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
    // POSIX calls, so that a failure says the OS's reason (errno), not a guess.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        throw std::runtime_error(path.string() + ": cannot be read (" + std::strerror(errno) + ")");
    std::string content;
    char buffer[65536];
    while (true) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            const int error = errno;
            ::close(fd);
            throw std::runtime_error(path.string() + ": cannot be read (" + std::strerror(error) + ")");
        }
        if (n == 0)
            break;
        content.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return content;
}

namespace {

// Writes all of `content` to `fd`; false with errno set on failure.
bool write_all(int fd, std::string_view content) {
    while (!content.empty()) {
        const ssize_t n = ::write(fd, content.data(), content.size());
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            if (n == 0)
                errno = EIO;
            return false;
        }
        content.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

} // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
    const auto fail = [&](int error) {
        throw std::runtime_error(path.string() + ": cannot be written (" + std::strerror(error) + ")");
    };
    // An existing target that is not a regular file (a device such as /dev/stdout, a pipe) is
    // written in place: renaming over it would replace the device itself.
    struct stat status {};
    if (::stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode)) {
        if (S_ISDIR(status.st_mode))
            fail(EISDIR);
        const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        if (fd < 0)
            fail(errno);
        if (!write_all(fd, content)) {
            const int error = errno;
            ::close(fd);
            fail(error);
        }
        if (::close(fd) != 0)
            fail(errno);
        return;
    }
    std::filesystem::path temporary = path;
    temporary += ".tmp";
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0)
        fail(errno);
    // From here on a failure removes the temporary file: nothing half-written is left behind.
    const auto fail_and_remove = [&](int error) {
        ::unlink(temporary.c_str());
        fail(error);
    };
    // Synced before the rename: otherwise a power cut may leave the new name on an empty file.
    if (!write_all(fd, content) || (syncs_enabled() && ::fdatasync(fd) != 0)) {
        const int error = errno;
        ::close(fd);
        fail_and_remove(error);
    }
    if (::close(fd) != 0) // NFS and some file systems report a full disk only here
        fail_and_remove(errno);
    if (::rename(temporary.c_str(), path.c_str()) != 0)
        fail_and_remove(errno);
    sync_directory(path.parent_path()); // the rename itself is durable only with its directory
}

} // namespace mhb
