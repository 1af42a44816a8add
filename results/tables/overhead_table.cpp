#include "results/tables/overhead_table.hpp"

#include "results/analysis/evaluation_time.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb {

namespace {

// An optimiser that does (almost) nothing but evaluate: its time is the floor the others' rows sit on.
bool is_floor(const std::string& algorithm) {
    return algorithm.substr(0, algorithm.find(':')) == "random-search";
}

// The floor's time on each problem, where random-search ran on it.
std::map<std::string, double> floors_of(const std::vector<EvaluationTime>& times) {
    std::map<std::string, double> floors;
    for (const auto& t : times)
        if (is_floor(t.algorithm))
            floors.emplace(t.problem, t.median_microseconds);
    return floors;
}

std::string overhead_caption(const StudyIndex& index, bool with_floor) {
    std::string caption =
        "Wall time per evaluation: for each run, its wall-clock seconds (timings.csv) x 1e6 / the "
        "evaluations it spent; the median over the runs. This is COCO's measure (the total time of a run "
        "per evaluation, the evaluation and the bookkeeping included), not the optimiser's own time";
    caption += with_floor
                   ? "; the last column subtracts random-search's median on the same problem (one uniform "
                     "point, its evaluation and the bookkeeping), which leaves the optimiser's overhead."
                   : "; add random-search to the study to see the floor of evaluation and bookkeeping.";
    return caption +
           " Times vary between machines and with the load: compare rows of one study, and run it with "
           "--threads 1 on an idle machine (mhbench run --study timing)." +
           left_out_notes(index);
}

} // namespace

std::optional<Table> overhead_table(const StudyIndex& index,
                                    const std::map<std::int64_t, double>& wall_seconds) {
    const std::vector<EvaluationTime> times = evaluation_times(index, wall_seconds);
    if (times.empty())
        return std::nullopt;
    const std::map<std::string, double> floors = floors_of(times);
    Table t;
    t.id = "overhead";
    t.title = "Wall time per evaluation per problem and algorithm (microseconds)";
    t.header = {"Problem", "Dimension", "Algorithm", "Runs", "Median time per evaluation (us)"};
    if (!floors.empty())
        t.header.push_back("Above random-search (us)");
    for (const auto& e : times) {
        std::vector<TableCell> row = {text_cell(e.problem), text_cell(std::to_string(e.dimension)),
                                      text_cell(index.label(e.algorithm)), text_cell(std::to_string(e.runs)),
                                      number_cell(e.median_microseconds, 3)};
        if (!floors.empty()) {
            const auto floor = floors.find(e.problem);
            row.push_back(floor == floors.end() ? tables::empty_cell()
                                                : number_cell(e.median_microseconds - floor->second, 3));
        }
        t.add_row(std::move(row));
    }
    t.caption = overhead_caption(index, !floors.empty());
    t.latex_note = "Median over runs of wall seconds x 1e6 / evaluations; machine-dependent (Methods).";
    t.methods = {t.caption.substr(0, t.caption.size() - left_out_notes(index).size())};
    t.latex_column(0).heading = true;
    t.latex_column(2).key = true;
    format_columns(t);
    return t;
}

} // namespace mhb
