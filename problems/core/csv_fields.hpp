// Splitting a line of a data CSV into its fields, and its errors, shared by the readers of
// problems/pmsm and problems/fluxmap: fields are separated by ',' and lose the blanks (and a CRLF file's
// '\r') at either end; there is no quoting, since data files hold numbers.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mhb {

// `s` without spaces, tabs and '\r' at either end ('\r' only at the end).
inline std::string_view trim_csv_field(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

// The trimmed fields of `line`, views into it; an empty line is one empty field.
inline std::vector<std::string_view> split_csv_fields(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t start = 0;
    while (true) {
        const auto comma = line.find(',', start);
        out.push_back(trim_csv_field(
            line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
        if (comma == std::string_view::npos)
            return out;
        start = comma + 1;
    }
}

// The one-line errors of a data file: "SOURCE: line N, what" for a defect of one line, "SOURCE:
// what" for one of the whole file. `source` must outlive it.
class CsvErrors {
public:
    explicit CsvErrors(const std::string& source) : source_(source) {}
    [[noreturn]] void fail(std::size_t line, const std::string& what) const {
        throw std::runtime_error(source_ + ": line " + std::to_string(line) + ", " + what);
    }
    [[noreturn]] void fail_file(const std::string& what) const {
        throw std::runtime_error(source_ + ": " + what);
    }

private:
    const std::string& source_;
};

} // namespace mhb
