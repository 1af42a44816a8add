// The text each run contributes to the rendered files, and their headers (see rendered_lines.hpp).
#include "results/store/rendered_lines.hpp"

#include "results/store/csv.hpp"
#include "results/store/runs_csv.hpp"

namespace mhb {

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
    block.run_line = runs_csv_line(r, columns);
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
