// load_study: a finished study directory read back into run records (see study_data.hpp).
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "results/store/crc32c.hpp"
#include "results/store/csv.hpp"
#include "results/store/runs_csv.hpp"
#include "results/store/store_check.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_marker.hpp"

namespace mhb {
namespace fs = std::filesystem;

namespace {

std::int64_t find_run(const std::map<std::int64_t, std::size_t>& index, const CsvTable& t, std::size_t row) {
    const std::int64_t id = t.integer(row, t.column("run_id"));
    if (index.find(id) == index.end())
        throw std::runtime_error(t.path.string() + ", line " + std::to_string(t.line_numbers[row]) +
                                 ": run_id " + std::to_string(id) + " is not in runs.csv");
    return id;
}

// The value of the line "name = value" of `text`, if it has one.
std::optional<std::string> marker_value(const std::string& text, const std::string& name) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind(name + " = ", 0) == 0)
            return line.substr(name.size() + 3);
    return std::nullopt;
}

// runs.csv must be the one rendered for this study.ini: two processes writing into one directory
// could leave one study's runs beside the other's study.ini. Markers from before the check name
// no study.ini, and are read as they are.
void check_runs_belong_to_study(const fs::path& dir, const StudyData& data, std::size_t runs,
                                const std::string& text) {
    const auto checksum = marker_value(text, "study.ini crc32c");
    if (checksum && *checksum != study_checksum(data.study_text))
        throw std::runtime_error((dir / StudyFiles::runs).string() +
                                 ": was rendered for another study.ini than the one beside it (crc32c " +
                                 *checksum + ", study.ini's is " + study_checksum(data.study_text) +
                                 "); run the study again to render it for this one");
    const auto count = marker_value(text, "runs");
    if (count && *count != std::to_string(runs))
        throw std::runtime_error((dir / StudyFiles::runs).string() + ": has " + std::to_string(runs) +
                                 (runs == 1 ? " row" : " rows") + ", but the study it was rendered for has " +
                                 *count + " runs");
}

// The marker's text, or "" for a study from before markers.
std::string marker_text(const fs::path& dir) {
    const fs::path marker = dir / StudyFiles::marker;
    return fs::exists(marker) ? read_whole_file(marker) : std::string();
}

// A file rendered from the store, read only when it is exactly what the study wrote: its size and
// CRC-32C are in the marker (not in markers from before the check), and the file itself was not
// synced, so a crash of the machine after the study finished may have left it short or stale.
CsvTable read_rendered_csv(const fs::path& dir, const char* name, const std::string& marker) {
    const fs::path path = dir / name;
    const auto written = marker_value(marker, name);
    if (!written)
        return read_csv(path);
    std::string text = read_whole_file(path);
    const std::string found = rendered_file_facts(text.size(), crc32c(text));
    if (found != *written)
        throw std::runtime_error(path.string() + ": is not the file the study wrote (" + found + ", not " +
                                 *written +
                                 "; the machine stopped before it reached the disk?); run the study's "
                                 "command again to render it from store.bin");
    std::istringstream in(std::move(text));
    return parse_csv(in, path);
}

// What makes `dir` a finished study: refused with a message saying what it is instead.
void check_finished_study(const fs::path& dir) {
    if (!fs::is_directory(dir))
        throw std::runtime_error(dir.string() + ": is not a directory");
    if (!fs::exists(dir / StudyFiles::runs) &&
        (fs::exists(dir / StudyFiles::store) || fs::exists(dir / StudyFiles::journal)))
        throw std::runtime_error(
            dir.string() + ": holds an unfinished study (no runs.csv yet); run the same command again to "
                           "complete it");
    if (!is_study_directory(dir))
        throw std::runtime_error(dir.string() + ": is not a mhbench study directory (no " +
                                 StudyFiles::marker + ", study.ini or runs.csv)");
}

// study.ini, context.ini and, when the study has one, algorithms.csv.
void read_study_description(const fs::path& dir, StudyData& data) {
    data.study_text = read_whole_file(dir / StudyFiles::study);
    data.context_text = read_whole_file(dir / StudyFiles::context);
    if (fs::exists(dir / StudyFiles::algorithms)) {
        const CsvTable algorithms = read_csv(dir / StudyFiles::algorithms);
        for (const auto& row : algorithms.rows)
            data.algorithms.push_back({row[algorithms.column("algorithm")], row[algorithms.column("label")],
                                       row[algorithms.column("parameters")]});
    }
}

// A run's position in StudyData::runs, by run_id.
using RunPositions = std::map<std::int64_t, std::size_t>;

RunPositions read_runs(const CsvTable& runs, StudyData& data) {
    RunsCsvLayout layout = runs_csv_layout(runs);
    data.parameter_columns = std::move(layout.parameters);
    RunPositions index;
    for (std::size_t row = 0; row < runs.rows.size(); ++row) {
        RunRecord r = read_runs_csv_row(runs, row, layout);
        if (index.count(r.run_id) != 0)
            throw std::runtime_error(runs.path.string() + ", line " + std::to_string(runs.line_numbers[row]) +
                                     ": run_id " + std::to_string(r.run_id) + " appears twice");
        index[r.run_id] = data.runs.size();
        data.runs.push_back(std::move(r));
    }
    return index;
}

void read_curves(const CsvTable& curves, const RunPositions& index, StudyData& data) {
    for (std::size_t row = 0; row < curves.rows.size(); ++row) {
        const auto id = find_run(index, curves, row);
        data.runs[index.at(id)].curve.push_back({curves.integer(row, curves.column("iteration")),
                                                 curves.integer(row, curves.column("evaluations")),
                                                 curves.number(row, curves.column("best_f")),
                                                 {}});
    }
}

void read_checkpoints(const CsvTable& checkpoints, const RunPositions& index, StudyData& data) {
    for (std::size_t row = 0; row < checkpoints.rows.size(); ++row) {
        const auto id = find_run(index, checkpoints, row);
        data.runs[index.at(id)].checkpoints.push_back(
            {checkpoints.integer(row, checkpoints.column("evaluations")),
             checkpoints.number(row, checkpoints.column("best_f"))});
    }
}

// Each row gives the best x of an iteration already read from curves.csv.
void read_trajectories(const CsvTable& trajectories, const RunPositions& index, StudyData& data) {
    for (std::size_t row = 0; row < trajectories.rows.size(); ++row) {
        const auto id = find_run(index, trajectories, row);
        RunRecord& r = data.runs[index.at(id)];
        const std::int64_t iteration = trajectories.integer(row, trajectories.column("iteration"));
        CurvePoint* point = nullptr;
        for (auto& p : r.curve)
            if (p.iteration == iteration)
                point = &p;
        if (point == nullptr)
            throw std::runtime_error(trajectories.path.string() + ", line " +
                                     std::to_string(trajectories.line_numbers[row]) + ": iteration " +
                                     std::to_string(iteration) + " of run " + std::to_string(id) +
                                     " is not in curves.csv");
        for (const auto& name : r.parameter_names)
            point->best_x.push_back(trajectories.number(row, trajectories.column(name)));
    }
}

void read_improvements_csv(const CsvTable& improvements, const RunPositions& index, StudyData& data) {
    const std::size_t event = improvements.column("event");
    const std::size_t evaluations = improvements.column("evaluations");
    const std::size_t f = improvements.column("f");
    for (std::size_t row = 0; row < improvements.rows.size(); ++row) {
        RunRecord& r = data.runs[index.at(find_run(index, improvements, row))];
        const std::string& kind = improvements.rows[row][event];
        if (kind != "improvement" && kind != "last")
            throw std::runtime_error(improvements.path.string() + ", line " +
                                     std::to_string(improvements.line_numbers[row]) + ", column 'event': '" +
                                     kind + "' is not improvement or last");
        ImprovementTrace& trace = r.improvements ? *r.improvements : r.improvements.emplace();
        if (kind == "last") {
            trace.last_f = improvements.number(row, f);
            continue;
        }
        const CheckpointSample point{improvements.integer(row, evaluations), improvements.number(row, f)};
        // Each improves on the one before: later, and strictly lower (which also rules out NaN).
        if (point.evaluations < 1 ||
            (!trace.points.empty() && (point.evaluations <= trace.points.back().evaluations ||
                                       !(point.best_f < trace.points.back().best_f))) ||
            std::isnan(point.best_f))
            throw std::runtime_error(improvements.path.string() + ", line " +
                                     std::to_string(improvements.line_numbers[row]) +
                                     ": not an improvement on the run's previous row");
        trace.points.push_back(point);
    }
}

void read_timings(const CsvTable& timings, const RunPositions& index, StudyData& data) {
    for (std::size_t row = 0; row < timings.rows.size(); ++row)
        data.wall_seconds[find_run(index, timings, row)] =
            timings.number(row, timings.column("wall_seconds"));
}

} // namespace

StudyData load_study(const fs::path& dir) {
    check_finished_study(dir);
    StudyData data;
    data.directory = dir;
    read_study_description(dir, data);
    const std::string marker = marker_text(dir);
    const CsvTable runs = read_rendered_csv(dir, StudyFiles::runs, marker);
    check_runs_belong_to_study(dir, data, runs.rows.size(), marker);
    const RunPositions index = read_runs(runs, data);
    read_curves(read_rendered_csv(dir, StudyFiles::curves, marker), index, data);
    read_checkpoints(read_rendered_csv(dir, StudyFiles::checkpoints, marker), index, data);
    read_trajectories(read_rendered_csv(dir, StudyFiles::trajectories, marker), index, data);
    // Studies written before improvements were recorded have no such file: their runs keep none.
    if (fs::exists(dir / StudyFiles::improvements))
        read_improvements_csv(read_rendered_csv(dir, StudyFiles::improvements, marker), index, data);
    read_timings(read_rendered_csv(dir, StudyFiles::timings, marker), index, data);
    // Without its marker (deleted, or not copied: `cp DIR/* NEW/` skips dot-files) nothing vouches
    // for the rendered files but the store they were rendered from.
    if (marker.empty() && fs::exists(dir / StudyFiles::store)) {
        check_rendered_files_against_store(dir, data, runs.line_numbers);
        data.warnings.push_back(dir.string() + ": has no " + StudyFiles::marker +
                                "; its files were checked against store.bin instead (they match, but their "
                                "number of runs is not checked against study.ini); run the study's command "
                                "again to restore it");
    }
    return data;
}

} // namespace mhb
