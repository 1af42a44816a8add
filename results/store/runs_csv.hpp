// runs.csv, a line per run: its header, a run's line and a line read back, all three built from the
// fields of run_fields.hpp, with the parameter columns (P, P_true, P_opt and P_err_pct for each
// named parameter of the study) laid out by hand. Internal to results/store: the writer renders
// the lines (rendered_lines.cpp), load_study reads them back (study_reader.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "results/store/csv.hpp"
#include "results/store/run_record.hpp"

namespace mhb {

// The header of runs.csv for the study's parameter columns.
std::string runs_csv_header(const std::vector<std::string>& parameter_columns);
// A run's line, for the study's parameter columns.
std::string runs_csv_line(const RunRecord& r, const std::vector<std::string>& parameter_columns);

// Where a runs.csv file has its parameter columns, found from its header.
struct RunsCsvLayout {
    static constexpr std::size_t per_parameter = 4; // P, P_true, P_opt, P_err_pct
    std::size_t first = 0;                          // the column of the first P
    std::size_t end = 0;                            // the column after the last P_err_pct
    std::vector<std::string> parameters;            // each P
};
// Throws std::runtime_error naming the file when the columns around the parameter columns are
// missing, or when these are not four per parameter.
RunsCsvLayout runs_csv_layout(const CsvTable& runs);

// The run on a row of runs.csv: every field of run_fields.hpp (its curve, checkpoints and
// improvements are in other files). Throws std::runtime_error naming the file, line and column of
// a cell that is not what runs.csv writes there.
RunRecord read_runs_csv_row(const CsvTable& runs, std::size_t row, const RunsCsvLayout& layout);

} // namespace mhb
