// The text each run contributes to the rendered files, and their headers (see rendered_lines.hpp).
#include "results/store/rendered_lines.hpp"

#include "results/store/csv.hpp"

namespace mhb {

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

// A run's line of runs.csv, for the study's parameter columns.
std::string run_line(const RunRecord& r, const std::vector<std::string>& columns) {
    std::string line = std::to_string(r.run_id) + ',' + csv_field(r.algorithm) + ',' + csv_field(r.problem) +
                       ',' + csv_field(r.budget) + ',' + std::to_string(r.run_index) + ',' +
                       std::to_string(r.seed) + ',' + (r.ok ? "ok" : "failed") + ',' +
                       std::to_string(r.evaluations) + ',' + std::to_string(r.iterations) + ',' +
                       (r.ok ? csv_number(r.best_f) : "") + ',' + csv_optional(r.f_opt) + ',' +
                       csv_optional(r.error()) + ',' +
                       (r.evaluations_to_target ? std::to_string(*r.evaluations_to_target) : "") + ',' +
                       join_numbers(r.best_x);
    for (const auto& column : columns) {
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
    return line + ',' + csv_field(r.message) + '\n';
}

} // namespace

void RenderedLines::append(const RenderedLines& other) {
    run_line += other.run_line;
    curve_lines += other.curve_lines;
    checkpoint_lines += other.checkpoint_lines;
    trajectory_lines += other.trajectory_lines;
    improvement_lines += other.improvement_lines;
    timing_line += other.timing_line;
}

RenderedLines render_run(const RunRecord& r, double wall_seconds, const std::vector<std::string>& columns) {
    RenderedLines block;
    const std::string id = std::to_string(r.run_id);
    block.run_line = run_line(r, columns);
    for (const auto& p : r.curve) {
        block.curve_lines += id + ',' + std::to_string(p.iteration) + ',' + std::to_string(p.evaluations) +
                             ',' + csv_number(p.best_f) + '\n';
        if (!r.parameter_names.empty() && !p.best_x.empty()) {
            std::string row = id + ',' + std::to_string(p.iteration);
            for (const auto& column : columns) {
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
    if (r.improvements) {
        for (const auto& p : r.improvements->points)
            block.improvement_lines +=
                id + ",improvement," + std::to_string(p.evaluations) + ',' + csv_number(p.best_f) + '\n';
        // Also marks the run as one whose improvements were recorded (it may have none: +inf only).
        block.improvement_lines +=
            id + ",last," + std::to_string(r.evaluations) + ',' + csv_number(r.improvements->last_f) + '\n';
    }
    block.timing_line = id + ',' + csv_number(wall_seconds) + '\n';
    return block;
}

std::string runs_csv_header(const std::vector<std::string>& parameter_columns) {
    std::string header =
        "run_id,algorithm,problem,budget,run,seed,status,evaluations,iterations,best_f,f_opt,error,"
        "evals_to_target,best_x";
    for (const auto& p : parameter_columns)
        header += "," + p + "," + p + "_true," + p + "_opt," + p + "_err_pct";
    return header + ",message\n";
}

RenderedLines rendered_headers(const std::vector<std::string>& parameter_columns) {
    RenderedLines headers;
    headers.run_line = runs_csv_header(parameter_columns);
    headers.curve_lines = "run_id,iteration,evaluations,best_f\n";
    headers.checkpoint_lines = "run_id,evaluations,best_f\n";
    headers.trajectory_lines = "run_id,iteration";
    for (const auto& p : parameter_columns)
        headers.trajectory_lines += "," + p;
    headers.trajectory_lines += '\n';
    headers.improvement_lines = "run_id,event,evaluations,f\n";
    headers.timing_line = "run_id,wall_seconds\n";
    return headers;
}

} // namespace mhb
