// Reading the embedded archives (libarchive: a tar of files each compressed by xz) and parsing the
// official data files.
#include "problems/cec/cec_data.hpp"

#include <algorithm>
#include <archive.h>
#include <archive_entry.h>
#include <charconv>
#include <map>
#include <mutex>
#include <stdexcept>

#include "problems/cec/cec_archives.hpp"

namespace mhb::cec {
namespace {

// Every file of one suite's archive, by its name without the "input_data/" folder and the ".xz":
// the file's xz-compressed bytes (each file is compressed alone, scripts/pack-cec-data.sh).
using CompressedMembers = std::map<std::string, std::string, std::less<>>;

using ArchiveReader = std::unique_ptr<archive, int (*)(archive*)>;

ArchiveReader open_reader(const void* bytes, std::size_t size, bool tar, const std::string& what) {
    // The reader is freed on every path out of its user.
    ArchiveReader reader(archive_read_new(), archive_read_free);
    if (!reader)
        throw std::runtime_error(what + "libarchive could not allocate a reader");
    if (tar) {
        archive_read_support_format_tar(reader.get());
    } else {
        archive_read_support_filter_xz(reader.get());
        archive_read_support_format_raw(reader.get());
    }
    if (archive_read_open_memory(reader.get(), bytes, size) != ARCHIVE_OK)
        throw std::runtime_error(what + archive_error_string(reader.get()));
    return reader;
}

// The current entry's data, all of it (`size` bytes when the header says, else to its end).
std::string read_entry(archive* reader, const std::string& what, const std::string& name) {
    std::string content;
    char buffer[1 << 16];
    for (;;) {
        const auto read = archive_read_data(reader, buffer, sizeof buffer);
        if (read < 0)
            throw std::runtime_error(what + "cannot read " + name + ": " + archive_error_string(reader));
        if (read == 0)
            return content;
        content.append(buffer, static_cast<std::size_t>(read));
    }
}

// The tar's members, still compressed: reading the index costs no decompression.
CompressedMembers index_archive(Suite suite) {
    const auto bytes = embedded_archive(suite);
    const std::string what = std::string(suite_name(suite)) + " data archive: ";
    const ArchiveReader reader = open_reader(bytes.data(), bytes.size(), true, what);
    CompressedMembers members;
    archive_entry* entry = nullptr;
    int status = ARCHIVE_OK;
    while ((status = archive_read_next_header(reader.get(), &entry)) == ARCHIVE_OK) {
        if (archive_entry_filetype(entry) != AE_IFREG)
            continue;
        std::string name = archive_entry_pathname(entry);
        if (const auto slash = name.rfind('/'); slash != std::string::npos)
            name.erase(0, slash + 1);
        if (!name.ends_with(".xz"))
            throw std::runtime_error(what + name + " is not an xz-compressed member");
        name.resize(name.size() - 3);
        std::string compressed = read_entry(reader.get(), what, name);
        members.emplace(std::move(name), std::move(compressed));
    }
    if (status != ARCHIVE_EOF)
        throw std::runtime_error(what + archive_error_string(reader.get()));
    return members;
}

// Indexed on first use and kept (3.2 MB for 2017); a file is decompressed only when asked for.
const CompressedMembers& members(Suite suite) {
    if (suite == Suite::cec2017) {
        static const CompressedMembers indexed = index_archive(Suite::cec2017);
        return indexed;
    }
    static const CompressedMembers indexed = index_archive(Suite::cec2022);
    return indexed;
}

std::string decompress(Suite suite, const std::string& name, const std::string& compressed) {
    const std::string what = std::string(suite_name(suite)) + " data archive: ";
    const ArchiveReader reader = open_reader(compressed.data(), compressed.size(), false, what);
    archive_entry* entry = nullptr;
    if (archive_read_next_header(reader.get(), &entry) != ARCHIVE_OK)
        throw std::runtime_error(what + "cannot decompress " + name + ": " +
                                 archive_error_string(reader.get()));
    return read_entry(reader.get(), what, name);
}

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// Whitespace-separated numbers as strtod/fscanf("%lf") read them (from_chars rounds the same way,
// correctly), line by line.
std::shared_ptr<const DataFile> parse(Suite suite, const std::string& name, std::string_view text) {
    auto file = std::make_shared<DataFile>();
    file->name = name;
    std::size_t line_number = 1;
    bool line_has_numbers = false;
    const char* p = text.data();
    const char* const end = p + text.size();
    while (p < end) {
        if (*p == '\n') {
            ++line_number;
            line_has_numbers = false;
            ++p;
            continue;
        }
        if (is_space(*p)) {
            ++p;
            continue;
        }
        const char* token_end = p;
        while (token_end < end && !is_space(*token_end))
            ++token_end;
        const char* first = *p == '+' ? p + 1 : p; // from_chars takes no leading '+'
        double value = 0;
        const auto [stop, error] = std::from_chars(first, token_end, value);
        if (error != std::errc() || stop != token_end)
            throw std::runtime_error(std::string(suite_name(suite)) + ": " + name + " line " +
                                     std::to_string(line_number) + ": '" + std::string(p, token_end) +
                                     "' is not a number");
        if (!line_has_numbers) {
            file->line_starts.push_back(file->numbers.size());
            line_has_numbers = true;
        }
        file->numbers.push_back(value);
        p = token_end;
    }
    return file;
}

std::string missing_message(Suite suite, std::string_view file_name) {
    return std::string(suite_name(suite)) + ": no data file " + std::string(file_name) +
           " in the official input data";
}

} // namespace

std::string_view suite_name(Suite suite) {
    return suite == Suite::cec2017 ? "cec2017" : "cec2022";
}

std::vector<double> DataFile::line_prefix(std::size_t line, std::size_t count) const {
    if (line >= line_starts.size())
        throw std::invalid_argument(name + " has " + std::to_string(line_starts.size()) +
                                    " lines of numbers, not " + std::to_string(line + 1));
    const std::size_t first = line_starts[line];
    const std::size_t line_end = line + 1 < line_starts.size() ? line_starts[line + 1] : numbers.size();
    if (line_end - first < count)
        throw std::invalid_argument(name + " line " + std::to_string(line + 1) + " has " +
                                    std::to_string(line_end - first) + " numbers, not " +
                                    std::to_string(count));
    return {numbers.begin() + static_cast<std::ptrdiff_t>(first),
            numbers.begin() + static_cast<std::ptrdiff_t>(first + count)};
}

std::vector<double> DataFile::range(std::size_t first, std::size_t count) const {
    if (first + count > numbers.size())
        throw std::invalid_argument(name + " has " + std::to_string(numbers.size()) + " numbers, not the " +
                                    std::to_string(first + count) + " needed");
    return {numbers.begin() + static_cast<std::ptrdiff_t>(first),
            numbers.begin() + static_cast<std::ptrdiff_t>(first + count)};
}

bool has_data_file(Suite suite, std::string_view file_name) {
    return members(suite).contains(file_name);
}

std::shared_ptr<const DataFile> data_file(Suite suite, std::string_view file_name) {
    static std::mutex mutex;
    static std::map<std::pair<Suite, std::string>, std::shared_ptr<const DataFile>, std::less<>> parsed;
    const auto& all = members(suite);
    const auto member = all.find(file_name);
    if (member == all.end())
        throw std::invalid_argument(missing_message(suite, file_name));
    const std::lock_guard lock(mutex);
    auto& slot = parsed[{suite, member->first}];
    if (!slot) // the text is dropped once parsed: only the numbers are kept
        slot = parse(suite, member->first, decompress(suite, member->first, member->second));
    return slot;
}

std::vector<std::string> data_file_names(Suite suite) {
    std::vector<std::string> names;
    for (const auto& [name, content] : members(suite))
        names.push_back(name);
    return names; // a std::map iterates in sorted order
}

std::string data_file_bytes(Suite suite, std::string_view file_name) {
    const auto& all = members(suite);
    const auto member = all.find(file_name);
    if (member == all.end())
        throw std::invalid_argument(missing_message(suite, file_name));
    return decompress(suite, member->first, member->second);
}

std::vector<std::pair<std::string, std::string>> recorded_sha256(Suite suite) {
    // Lines "<64 hex>  <year>/input_data/<name>", as sha256sum writes them.
    const std::string prefix = suite == Suite::cec2017 ? "2017/input_data/" : "2022/input_data/";
    std::vector<std::pair<std::string, std::string>> out;
    const std::string_view text = embedded_sha256sums();
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t stop = text.find('\n', start);
        if (stop == std::string_view::npos)
            stop = text.size();
        const std::string_view line = text.substr(start, stop - start);
        start = stop + 1;
        if (line.size() < 66 || line.substr(64, 2) != "  ")
            continue;
        const std::string_view path = line.substr(66);
        if (path.starts_with(prefix))
            out.emplace_back(std::string(path.substr(prefix.size())), std::string(line.substr(0, 64)));
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace mhb::cec
