// load_study: a finished study directory read back into run records (see study_data.hpp).
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "results/store/crc32c.hpp"
#include "results/store/csv.hpp"
#include "results/store/store_check.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_marker.hpp"

namespace mhb {
namespace fs = std::filesystem;

namespace {

std::vector<double> split_numbers(const CsvTable& t, std::size_t row, std::size_t column) {
    std::vector<double> values;
    const std::string& text = t.rows[row][column];
    std::size_t i = 0;
    while (i < text.size()) {
        const auto j = std::min(text.find(' ', i), text.size());
        double v = 0;
        const auto [ptr, ec] = std::from_chars(text.data() + i, text.data() + j, v);
        if (ec != std::errc() || ptr != text.data() + j)
            throw std::runtime_error(t.path.string() + ", line " + std::to_string(t.line_numbers[row]) +
                                     ", column '" + t.header[column] + "': not a list of numbers");
        values.push_back(v);
        i = j + 1;
    }
    return values;
}

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

// Where runs.csv's parameter columns are: P, P_true, P_opt and P_err_pct for each named parameter,
// from the column after best_x up to message.
struct ParameterColumns {
    static constexpr std::size_t per_parameter = 4;
    std::size_t first = 0;
    std::size_t message = 0;
};

ParameterColumns parameter_columns(const CsvTable& runs, std::vector<std::string>& names) {
    ParameterColumns columns{runs.column("best_x") + 1, runs.column("message")};
    if (columns.message < columns.first || (columns.message - columns.first) % columns.per_parameter != 0)
        throw std::runtime_error(runs.path.string() + ": parameter columns are malformed");
    for (std::size_t c = columns.first; c < columns.message; c += columns.per_parameter)
        names.push_back(runs.header[c]);
    return columns;
}

// The named parameters a run has values for, with their true values and optima when it has them
// for all.
void read_parameters(const CsvTable& runs, std::size_t row, const ParameterColumns& columns, RunRecord& r) {
    bool all_truths = true;
    bool all_optima = true;
    for (std::size_t c = columns.first; c < columns.message; c += columns.per_parameter) {
        if (runs.rows[row][c].empty())
            continue;
        r.parameter_names.push_back(runs.header[c]);
        const auto truth = runs.optional_number(row, c + 1);
        all_truths = all_truths && truth.has_value();
        r.true_parameters.push_back(truth.value_or(0.0));
        const auto optimum = runs.optional_number(row, c + 2);
        all_optima = all_optima && optimum.has_value();
        r.x_opt.push_back(optimum.value_or(0.0));
    }
    if (!all_truths)
        r.true_parameters.clear();
    if (!all_optima)
        r.x_opt.clear();
}

// One row of runs.csv.
RunRecord read_run(const CsvTable& runs, std::size_t row, const ParameterColumns& columns) {
    const auto col = [&](const char* name) { return runs.column(name); };
    const auto refuse = [&](const std::string& what) {
        return std::runtime_error(runs.path.string() + ", line " + std::to_string(runs.line_numbers[row]) +
                                  what);
    };
    RunRecord r;
    r.run_id = runs.integer(row, col("run_id"));
    r.algorithm = runs.rows[row][col("algorithm")];
    r.problem = runs.rows[row][col("problem")];
    // Studies written before budgets were recorded have no budget column.
    if (runs.has_column("budget"))
        r.budget = runs.rows[row][col("budget")];
    r.run_index = runs.integer(row, col("run"));
    const std::string& seed = runs.rows[row][col("seed")];
    if (std::from_chars(seed.data(), seed.data() + seed.size(), r.seed).ec != std::errc())
        throw refuse(", column 'seed': not an unsigned integer");
    const std::string& status = runs.rows[row][col("status")];
    if (status != "ok" && status != "failed")
        throw refuse(", column 'status': '" + status + "' is not ok or failed");
    r.ok = status == "ok";
    r.evaluations = runs.integer(row, col("evaluations"));
    r.iterations = runs.integer(row, col("iterations"));
    if (r.ok)
        r.best_f = runs.number(row, col("best_f"));
    r.f_opt = runs.optional_number(row, col("f_opt"));
    // Written as an integer; read as one, so that no text (1e300, nan) becomes a cast out of range.
    if (!runs.rows[row][col("evals_to_target")].empty())
        r.evaluations_to_target = runs.integer(row, col("evals_to_target"));
    r.best_x = split_numbers(runs, row, col("best_x"));
    read_parameters(runs, row, columns, r);
    r.message = runs.rows[row][columns.message];
    return r;
}

// A run's position in StudyData::runs, by run_id.
using RunPositions = std::map<std::int64_t, std::size_t>;

RunPositions read_runs(const CsvTable& runs, StudyData& data) {
    const ParameterColumns columns = parameter_columns(runs, data.parameter_columns);
    RunPositions index;
    for (std::size_t row = 0; row < runs.rows.size(); ++row) {
        RunRecord r = read_run(runs, row, columns);
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
