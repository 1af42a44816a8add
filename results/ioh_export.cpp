#include "results/ioh_export.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>

#include "results/csv.hpp"

namespace mhb {

namespace fs = std::filesystem;

namespace {

// Names in IOH file names may not hold path separators or spaces.
std::string file_name_part(const std::string& text) {
    std::string out;
    for (char c : text)
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ? c : '_';
    return out;
}

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        if (static_cast<unsigned char>(c) < 0x20)
            continue; // control characters never occur in specs; drop rather than escape
        out += c;
    }
    return out + "\"";
}

// A JSON number (JSON has no nan/inf: those become null).
std::string json_number(double value) {
    return std::isfinite(value) ? csv_number(value) : "null";
}

using Points = std::vector<std::pair<std::int64_t, double>>;

// The run's best-so-far as recorded, reduced to its strict improvements, by evaluations; points
// whose f is not finite are left out and counted in `left_out`.
std::vector<std::pair<std::int64_t, double>> improvements(const RunRecord& r, std::size_t& left_out) {
    std::vector<std::pair<std::int64_t, double>> points;
    for (const auto& p : r.curve)
        points.emplace_back(p.evaluations, p.best_f);
    for (const auto& c : r.checkpoints)
        points.emplace_back(c.evaluations, c.best_f);
    std::stable_sort(points.begin(), points.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::pair<std::int64_t, double>> out;
    for (const auto& p : points) {
        if (p.first <= 0)
            continue;
        if (!std::isfinite(p.second))
            ++left_out;
        else if (out.empty() || p.second < out.back().second)
            out.push_back(p);
    }
    if (std::isfinite(r.best_f) && (out.empty() || r.best_f < out.back().second))
        out.emplace_back(r.evaluations, r.best_f);
    return out;
}

} // namespace

IohExportSummary write_ioh_export(const StudyIndex& index, const fs::path& dir) {
    IohExportSummary summary;
    for (const auto& algorithm : index.algorithms()) {
        const fs::path folder = dir / file_name_part(algorithm);
        for (std::size_t f = 0; f < index.problems().size(); ++f) {
            const std::string& problem = index.problems()[f];
            const RunGroup* group = index.find(problem, algorithm);
            if (group == nullptr)
                continue;
            const std::string id = std::to_string(f + 1);
            const std::string name = file_name_part(problem);
            // Runs grouped by dimension (one problem spec has one dimension; kept general).
            std::map<std::size_t, std::vector<std::pair<const RunRecord*, Points>>> by_dimension;
            for (const auto* r : group->runs) {
                std::size_t left_out = 0;
                Points points = improvements(*r, left_out);
                if (points.empty()) { // nothing finite to show: the run ended at +inf
                    ++summary.runs_left_out;
                    continue;
                }
                summary.points_left_out += left_out;
                by_dimension[r->best_x.size()].emplace_back(r, std::move(points));
            }
            if (by_dimension.empty())
                continue;
            std::string scenarios;
            for (const auto& [dimension, runs] : by_dimension) {
                const std::string dat_relative = "data_f" + id + "_" + name + "/IOHprofiler_f" + id + "_DIM" +
                                                 std::to_string(dimension) + ".dat";
                std::string dat;
                std::string run_entries;
                for (const auto& [r, points] : runs) {
                    dat += "evaluations raw_y\n";
                    for (const auto& [evaluations, y] : points)
                        dat += std::to_string(evaluations) + ' ' + csv_number(y) + '\n';
                    std::string x;
                    for (std::size_t k = 0; k < r->best_x.size(); ++k)
                        x += (k == 0 ? "" : ", ") + json_number(r->best_x[k]);
                    run_entries += std::string(run_entries.empty() ? "" : ",\n") +
                                   "\t\t\t\t{\"instance\": 1, \"evals\": " + std::to_string(r->evaluations) +
                                   ", \"best\": {\"evals\": " + std::to_string(points.back().first) +
                                   ", \"y\": " + json_number(r->best_f) + ", \"x\": [" + x + "]}}";
                }
                fs::create_directories(folder / ("data_f" + id + "_" + name));
                write_file_atomically(folder / dat_relative, dat);
                ++summary.files;
                scenarios += std::string(scenarios.empty() ? "" : ",\n") +
                             "\t\t{\"dimension\": " + std::to_string(dimension) +
                             ",\n\t\t\"path\": " + json_string(dat_relative) + ",\n\t\t\"runs\": [\n" +
                             run_entries + "\n\t\t]}";
            }
            const std::string json =
                "{\n\t\"version\": \"0.3.3\",\n\t\"suite\": \"mhbench\",\n\t\"function_id\": " + id +
                ",\n\t\"function_name\": " + json_string(name) +
                ",\n\t\"maximization\": false,\n\t\"algorithm\": {\"name\": " +
                json_string(index.label(algorithm)) + ", \"info\": " +
                json_string("mhbench run of " + index.full_spec(algorithm) + " on " + problem) +
                "},\n\t\"attributes\": [\"evaluations\", \"raw_y\"],\n\t\"scenarios\": [\n" + scenarios +
                "\n\t]\n}\n";
            write_file_atomically(folder / ("IOHprofiler_f" + id + "_" + name + ".json"), json);
            ++summary.files;
        }
    }
    return summary;
}

} // namespace mhb
