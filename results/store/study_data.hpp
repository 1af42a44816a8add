// A finished study directory read back: its description, its runs with their curves, checkpoints
// and improvements, and its timings (load_study, study_reader.cpp). Every report starts here.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "results/store/algorithm_info.hpp"
#include "results/store/run_record.hpp"

namespace mhb {

struct StudyData {
    std::filesystem::path directory;
    std::string study_text;
    std::string context_text;
    std::vector<std::string> parameter_columns;
    // In study order; empty for studies written before algorithms.csv existed (then label and
    // full spec are the spec itself).
    std::vector<AlgorithmInfo> algorithms;
    std::vector<RunRecord> runs; // sorted by run_id, with curve, checkpoints and improvements filled in
    std::map<std::int64_t, double> wall_seconds;
    // What the reader has to say about the directory, one line each: a study without its marker.
    std::vector<std::string> warnings;
};

// Reads a finished study directory. Throws std::runtime_error naming the file (and line) when
// a file is missing, truncated or malformed, or when the directory holds an unfinished study. The
// rendered files must be those the marker names (size and CRC-32C); without a marker, those of a
// study with store.bin must be what it renders (store_check.hpp), and a study of format 2 (no
// store.bin) is read as it is.
StudyData load_study(const std::filesystem::path& dir);

} // namespace mhb
