// .mhbench-study, the marker of a study directory: what makes a directory a study, and the text
// that names, once the study is finished, the study.ini its runs.csv was rendered for and the size
// and checksum of every rendered file (study_marker.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mhb {

// True when `dir` is a mhbench study directory (see study_files.hpp).
bool is_study_directory(const std::filesystem::path& dir);

// A file rendered from the store (runs.csv, curves.csv, ...) as it was written: its size and
// CRC-32C. These files are not synced (the store they are rendered from is, and they are 100 MB
// for 10^5 runs): the marker, which is synced, names them, and load_study refuses any that a
// crash of the machine left different (rendered again by running the same command again).
struct RenderedFile {
    std::string name;
    std::uint64_t size = 0;
    std::uint32_t checksum = 0; // CRC-32C
};

// The text of .mhbench-study: the format, and once a study is finished, the checksum of the
// study.ini its runs.csv was rendered for, the number of runs in it (`runs` < 0: unfinished) and
// each rendered file's size and checksum ("runs.csv = 1234 bytes, crc32c 0a1b2c3d").
std::string study_marker(std::string_view study_text, std::int64_t runs = -1,
                         const std::vector<RenderedFile>& rendered = {});
// The CRC-32C of a study.ini's text, in hex, as the marker names it.
std::string study_checksum(std::string_view study_text);
// How the marker states a rendered file: "1234 bytes, crc32c 0a1b2c3d".
std::string rendered_file_facts(std::uint64_t size, std::uint32_t checksum);

} // namespace mhb
