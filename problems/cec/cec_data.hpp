// The official input data of the CEC 2017 and CEC 2022 bound-constrained suites (shift vectors,
// rotation matrices, shuffle permutations), shipped inside the executable as the original files,
// byte for byte, each compressed alone, in one tar per suite (problems/cec/data/, made by
// scripts/pack-cec-data.sh).
//
// A suite's archive is indexed the first time any of its files is asked for; a file is decompressed
// and parsed the first time it is asked for, and only its numbers are kept, for the life of the
// process, shared read-only by every problem and run. Everything here is thread-safe.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace mhb::cec {

enum class Suite { cec2017, cec2022 };

// "cec2017" or "cec2022".
std::string_view suite_name(Suite suite);

// One data file parsed as the official code reads it: whitespace-separated numbers, with the line
// structure kept because composition functions take o_k from the first D numbers of line k.
struct DataFile {
    std::string name;                     // e.g. "M_21_D10.txt"
    std::vector<double> numbers;          // every number, in file order
    std::vector<std::size_t> line_starts; // index in `numbers` of the first number of each line
                                          // that holds any (empty lines are skipped)

    // The first `count` numbers of line `line` (0-based among non-empty lines). Throws
    // std::invalid_argument naming the file when the line is missing or shorter than `count`.
    std::vector<double> line_prefix(std::size_t line, std::size_t count) const;
    // Numbers [first, first + count) of the whole stream; throws as above when the file is short.
    std::vector<double> range(std::size_t first, std::size_t count) const;
};

// True when the suite's archive holds `file_name` (e.g. "shuffle_data_11_D10.txt").
bool has_data_file(Suite suite, std::string_view file_name);

// The parsed file. Throws std::invalid_argument ("cec2017: no data file M_11_D20.txt") when the
// archive does not hold it, std::runtime_error when a token is not a number.
std::shared_ptr<const DataFile> data_file(Suite suite, std::string_view file_name);

// Every member's name (e.g. "input_data/M_1_D10.txt" is listed as "M_1_D10.txt"), sorted.
std::vector<std::string> data_file_names(Suite suite);

// The original bytes of one file, exactly as published (CRLF kept): for the SHA-256 check.
// Decompressed at each call, not kept.
std::string data_file_bytes(Suite suite, std::string_view file_name);

// The SHA-256 of every original file, as recorded when the archive was made
// (problems/cec/data/SHA256SUMS, copied from ../shared/cec/SHA256SUMS): name -> hex digest.
std::vector<std::pair<std::string, std::string>> recorded_sha256(Suite suite);

} // namespace mhb::cec
