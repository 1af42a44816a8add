// What each run contributes to the files rendered from store.bin (runs.csv, curves.csv, ...), and
// their headers: shared by StudyWriter::finish(), which writes them, and load_study, which checks
// them against store.bin when a study has lost its marker (store_check.hpp). Internal to
// results/store.
#pragma once

#include <string>
#include <vector>

#include "results/store/run_record.hpp"
#include "results/store/study_files.hpp"

namespace mhb {

// The text of each rendered file, for some runs (or the headers).
struct RenderedLines {
    std::string run_line;
    std::string curve_lines;
    std::string checkpoint_lines;
    std::string trajectory_lines;
    std::string improvement_lines;
    std::string timing_line;

    void append(const RenderedLines& other);
};

// Each rendered file with its part of RenderedLines, in the order finish() writes them.
struct RenderedFileText {
    const char* name;
    std::string RenderedLines::*text;
};
inline constexpr RenderedFileText rendered_file_texts[] = {
    {StudyFiles::runs, &RenderedLines::run_line},
    {StudyFiles::curves, &RenderedLines::curve_lines},
    {StudyFiles::checkpoints, &RenderedLines::checkpoint_lines},
    {StudyFiles::trajectories, &RenderedLines::trajectory_lines},
    {StudyFiles::improvements, &RenderedLines::improvement_lines},
    {StudyFiles::timings, &RenderedLines::timing_line},
};

// The lines a run contributes to each file, for the study's parameter columns.
RenderedLines render_run(const RunRecord& r, double wall_seconds, const std::vector<std::string>& columns);

// The header line of each file.
RenderedLines rendered_headers(const std::vector<std::string>& parameter_columns);

} // namespace mhb
