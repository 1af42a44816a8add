// Reading and writing the PMSM dataset CSV (ARCHITECTURE.md section 10): optional `# key=value` metadata
// lines, the header `t,ud,uq,id,iq,omega` (any order) with an optional `injected` column (0/1), then one row
// per sample in s, V, V, A, A, electrical rad/s. Without `injected`, a sample counts as injected
// when |id| exceeds a threshold (default 1 A, half the paper's -2 A injection).
//
// The reader checks everything and throws std::runtime_error naming the file, the line (row) and
// the column, e.g. `drive.csv: line 57, column 'ud': 'abc' is not a number`. A UTF-8 byte-order
// mark at the start is skipped; a cell is quoted in an error to at most 40 characters. Every
// value must lie within +-max_dataset_magnitude: a drive's volts, amperes, rad/s and seconds are
// far inside it, and the least squares square products of three values (omega i_q L), so 1e9 keeps
// every sum of squares below 1e60, far from overflow; a file beyond it is damaged or in wrong units.
#pragma once

#include <iosfwd>
#include <string>

#include "problems/pmsm/dataset.hpp"

namespace mhb::pmsm {

inline constexpr double max_dataset_magnitude = 1e9;

struct DatasetReadOptions {
    double injection_threshold = 1.0; // A; used only when the file has no `injected` column
    std::size_t min_rows = 4;         // fewer data rows is an error
    // The steady-state model needs samples of both injection states; the dynamic and output-error
    // models and `mhbench identify` read any window and judge what it determines.
    bool require_both_states = true;
};

// Reads the file once; when `sha256` is given it receives the SHA-256 of exactly the bytes parsed.
Dataset read_dataset_csv(const std::string& path, const DatasetReadOptions& options = {},
                         std::string* sha256 = nullptr);
// `source` names the stream in error messages.
Dataset read_dataset_csv(std::istream& in, const std::string& source, const DatasetReadOptions& options = {});

// Writes metadata, the header with the `injected` column, and every number as the shortest text
// that reads back to the same double (so write + read reproduces the dataset bit for bit).
void write_dataset_csv(std::ostream& out, const Dataset& data);
void write_dataset_csv(const std::string& path, const Dataset& data);

} // namespace mhb::pmsm
