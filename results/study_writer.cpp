// StudyWriter: the journal of finished runs, resuming, and the sorted result files (see store.hpp).
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "results/csv.hpp"
#include "results/store.hpp"

namespace mhb {
namespace fs = std::filesystem;

namespace {

std::string join_numbers(const std::vector<double>& values) {
    std::string out;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0)
            out += ' ';
        out += csv_number(values[i]);
    }
    return out;
}

const char* const result_files[] = {StudyFiles::runs,         StudyFiles::curves,  StudyFiles::checkpoints,
                                    StudyFiles::trajectories, StudyFiles::timings, StudyFiles::journal};

} // namespace

std::string runs_csv_header(const std::vector<std::string>& parameter_columns) {
    std::string header =
        "run_id,algorithm,problem,budget,run,seed,status,evaluations,iterations,best_f,f_opt,error,"
        "evals_to_target,best_x";
    for (const auto& p : parameter_columns)
        header += "," + p + "," + p + "_true," + p + "_opt," + p + "_err_pct";
    return header + ",message\n";
}

bool is_study_directory(const fs::path& dir) {
    std::error_code ec;
    if (fs::exists(dir / StudyFiles::marker, ec))
        return true;
    return fs::exists(dir / StudyFiles::study, ec) &&
           (fs::exists(dir / StudyFiles::runs, ec) || fs::exists(dir / StudyFiles::journal, ec));
}

StudyWriter::StudyWriter(fs::path dir, std::string study_text, std::string context_text,
                         std::vector<std::string> parameter_columns, bool overwrite,
                         const std::vector<AlgorithmInfo>& algorithms)
    : dir_(std::move(dir)), parameter_columns_(std::move(parameter_columns)) {
    std::error_code ec;
    if (fs::is_directory(dir_, ec) && !fs::is_empty(dir_, ec) && !is_study_directory(dir_))
        throw std::runtime_error(dir_.string() + ": is not empty and is not a mhbench study (it has no " +
                                 StudyFiles::marker +
                                 "); its files are left alone: choose a new or empty --out");
    fs::create_directories(dir_, ec);
    if (ec || !fs::is_directory(dir_))
        throw std::runtime_error(dir_.string() + ": cannot create the output directory (" +
                                 (ec ? ec.message() : std::string("not a directory")) + ")");
    const bool finished = fs::exists(dir_ / StudyFiles::runs);
    const bool unfinished = fs::exists(dir_ / StudyFiles::journal);
    bool resume = false;
    if (finished && !overwrite)
        throw std::runtime_error(dir_.string() +
                                 ": holds a finished study; choose another --out or pass --overwrite");
    if (!finished && unfinished) {
        std::string previous;
        if (fs::exists(dir_ / StudyFiles::study))
            previous = read_whole_file(dir_ / StudyFiles::study);
        resume = previous == study_text;
        if (!resume && !overwrite)
            throw std::runtime_error(dir_.string() +
                                     ": holds an unfinished run of another study; choose another --out or "
                                     "pass --overwrite");
    }
    if (!resume)
        for (const char* name : result_files)
            fs::remove(dir_ / name, ec);
    write_file_atomically(dir_ / StudyFiles::marker, "mhbench study directory, format 2\n");
    write_file_atomically(dir_ / StudyFiles::study, study_text);
    write_file_atomically(dir_ / StudyFiles::context, context_text);
    if (algorithms.empty()) {
        fs::remove(dir_ / StudyFiles::algorithms, ec);
    } else {
        std::string table = "algorithm,label,parameters\n";
        for (const auto& a : algorithms)
            table += csv_field(a.spec) + ',' + csv_field(a.label) + ',' + csv_field(a.full_spec) + '\n';
        write_file_atomically(dir_ / StudyFiles::algorithms, table);
    }
    if (resume)
        load_journal();
}

StudyWriter::Block StudyWriter::render(const RunRecord& r, double wall_seconds) const {
    Block block;
    const std::string id = std::to_string(r.run_id);
    std::string line =
        id + ',' + csv_field(r.algorithm) + ',' + csv_field(r.problem) + ',' + csv_field(r.budget) + ',' +
        std::to_string(r.run_index) + ',' + std::to_string(r.seed) + ',' + (r.ok ? "ok" : "failed") + ',' +
        std::to_string(r.evaluations) + ',' + std::to_string(r.iterations) + ',' +
        (r.ok ? csv_number(r.best_f) : "") + ',' + csv_optional(r.f_opt) + ',' + csv_optional(r.error()) +
        ',' + (r.evaluations_to_target ? std::to_string(*r.evaluations_to_target) : "") + ',' +
        join_numbers(r.best_x);
    for (const auto& column : parameter_columns_) {
        std::string value;
        std::string truth;
        std::string optimum;
        std::string error;
        for (std::size_t k = 0; k < r.parameter_names.size(); ++k) {
            if (r.parameter_names[k] != column || k >= r.best_x.size())
                continue;
            value = csv_number(r.best_x[k]);
            if (k < r.x_opt.size())
                optimum = csv_number(r.x_opt[k]);
            if (k < r.true_parameters.size()) {
                truth = csv_number(r.true_parameters[k]);
                if (r.true_parameters[k] != 0.0)
                    error = csv_number(100.0 * (r.best_x[k] - r.true_parameters[k]) / r.true_parameters[k]);
            }
        }
        line += ',' + value + ',' + truth + ',' + optimum + ',' + error;
    }
    block.run_line = line + ',' + csv_field(r.message) + '\n';

    for (const auto& p : r.curve) {
        block.curve_lines += id + ',' + std::to_string(p.iteration) + ',' + std::to_string(p.evaluations) +
                             ',' + csv_number(p.best_f) + '\n';
        if (!r.parameter_names.empty() && !p.best_x.empty()) {
            std::string row = id + ',' + std::to_string(p.iteration);
            for (const auto& column : parameter_columns_) {
                std::string value;
                for (std::size_t k = 0; k < r.parameter_names.size(); ++k)
                    if (r.parameter_names[k] == column && k < p.best_x.size())
                        value = csv_number(p.best_x[k]);
                row += ',' + value;
            }
            block.trajectory_lines += row + '\n';
        }
    }
    for (const auto& c : r.checkpoints)
        block.checkpoint_lines +=
            id + ',' + std::to_string(c.evaluations) + ',' + csv_number(c.best_f) + '\n';
    block.timing_line = id + ',' + csv_number(wall_seconds) + '\n';
    return block;
}

namespace {

// Journal lines: "begin ID", then "R|C|K|T|W <csv line>", then "end ID". A block without its
// "end" line (the process died while writing it) is dropped on resume.
void append_tagged(std::string& out, char tag, const std::string& lines) {
    std::size_t start = 0;
    while (start < lines.size()) {
        const auto end = lines.find('\n', start);
        out += tag;
        out += ' ';
        out.append(lines, start, end - start + 1);
        start = end + 1;
    }
}

std::string journal_text(std::int64_t id, const std::string& run, const std::string& curves,
                         const std::string& checkpoints, const std::string& trajectories,
                         const std::string& timing) {
    std::string text = "begin " + std::to_string(id) + '\n';
    append_tagged(text, 'R', run);
    append_tagged(text, 'C', curves);
    append_tagged(text, 'K', checkpoints);
    append_tagged(text, 'T', trajectories);
    append_tagged(text, 'W', timing);
    return text + "end " + std::to_string(id) + '\n';
}

} // namespace

void StudyWriter::load_journal() {
    std::ifstream in(dir_ / StudyFiles::journal, std::ios::binary);
    std::string line;
    Block current;
    std::int64_t current_id = -1;
    bool in_block = false;
    while (std::getline(in, line)) {
        if (in.eof())
            break; // a last line without its newline was cut short
        if (line.rfind("begin ", 0) == 0) {
            current = Block{};
            in_block =
                std::from_chars(line.data() + 6, line.data() + line.size(), current_id).ec == std::errc();
        } else if (line.rfind("end ", 0) == 0) {
            std::int64_t id = -2;
            std::from_chars(line.data() + 4, line.data() + line.size(), id);
            if (in_block && id == current_id && !current.run_line.empty()) {
                blocks_[id] = current;
                completed_.insert(id);
            }
            in_block = false;
        } else if (in_block && line.size() >= 2 && line[1] == ' ') {
            const std::string content = line.substr(2) + '\n';
            switch (line[0]) {
            case 'R':
                current.run_line += content;
                break;
            case 'C':
                current.curve_lines += content;
                break;
            case 'K':
                current.checkpoint_lines += content;
                break;
            case 'T':
                current.trajectory_lines += content;
                break;
            case 'W':
                current.timing_line += content;
                break;
            default:
                in_block = false;
            }
        } else {
            in_block = false;
        }
    }
    // Rewrite the journal with the complete blocks only, so that new blocks never follow a
    // half-written line.
    std::string text;
    for (const auto& [id, b] : blocks_)
        text += journal_text(id, b.run_line, b.curve_lines, b.checkpoint_lines, b.trajectory_lines,
                             b.timing_line);
    write_file_atomically(dir_ / StudyFiles::journal, text);
}

void StudyWriter::append(const RunRecord& record, double wall_seconds) {
    Block block = render(record, wall_seconds);
    const std::string text = journal_text(record.run_id, block.run_line, block.curve_lines,
                                          block.checkpoint_lines, block.trajectory_lines, block.timing_line);
    const std::lock_guard<std::mutex> lock(mutex_);
    std::ofstream out(dir_ / StudyFiles::journal, std::ios::binary | std::ios::app);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out)
        throw std::runtime_error((dir_ / StudyFiles::journal).string() + ": writing failed (" +
                                 std::strerror(errno) + ")");
    blocks_[record.run_id] = std::move(block);
    completed_.insert(record.run_id);
}

void StudyWriter::finish() {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::string runs = runs_csv_header(parameter_columns_);
    std::string curves = "run_id,iteration,evaluations,best_f\n";
    std::string checkpoints = "run_id,evaluations,best_f\n";
    std::string trajectories = "run_id,iteration";
    for (const auto& p : parameter_columns_)
        trajectories += "," + p;
    trajectories += '\n';
    std::string timings = "run_id,wall_seconds\n";
    for (const auto& [id, b] : blocks_) {
        runs += b.run_line;
        curves += b.curve_lines;
        checkpoints += b.checkpoint_lines;
        trajectories += b.trajectory_lines;
        timings += b.timing_line;
    }
    write_file_atomically(dir_ / StudyFiles::curves, curves);
    write_file_atomically(dir_ / StudyFiles::checkpoints, checkpoints);
    write_file_atomically(dir_ / StudyFiles::trajectories, trajectories);
    write_file_atomically(dir_ / StudyFiles::timings, timings);
    write_file_atomically(dir_ / StudyFiles::runs, runs);
    std::error_code ec;
    fs::remove(dir_ / StudyFiles::journal, ec);
}

} // namespace mhb
