// The result files the CEC organisers ask for (results/analysis/cec_protocol.hpp), written by the report of
// a study that follows a protocol: in one folder, "<Algorithm>_<F>_<D>.txt" for every algorithm,
// function F and dimension D, the errors of the runs as a matrix, a row per checkpoint (CEC 2022:
// then FEterm) and a column per run (by run index; failed runs left out), each value the shortest
// text that reads back exactly, separated by spaces (MATLAB's load and NumPy's loadtxt read it).
// A README beside them says what the rows and columns are, the evaluation count of every
// checkpoint per dimension, and which algorithm each file name stands for.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "results/analysis/cec_protocol.hpp" // exports read analyses, not tables
#include "results/store/study_index.hpp"     // runs, grouped: every room reads them here

namespace mhb {

// The matrix of one file: a row per checkpoint (and FEterm when the protocol has it), a column per run.
std::string cec_result_matrix(const CecProtocol& protocol, const std::vector<const RunRecord*>& runs,
                              std::int64_t max_fes, std::int64_t dimension);

// "<Algorithm>_<F>_<D>.txt" with the label made safe for a file name: anything but letters,
// digits, '.', '+' and '-' becomes '-', so '_' only separates the three parts.
std::string cec_file_name(const std::string& label, int function, std::int64_t dimension);

struct CecFilesSummary {
    std::size_t files = 0;
    std::size_t failed_runs = 0; // left out of the files
};

// Writes every file of the index's problems of the protocol's family, and the README, into `dir`
// (created; .txt files of an earlier report removed first: they may name algorithms no longer there).
// Throws std::runtime_error when a file cannot be written.
CecFilesSummary write_cec_result_files(const StudyIndex& index, const CecProtocol& protocol,
                                       const std::filesystem::path& dir);

} // namespace mhb
