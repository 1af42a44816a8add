#include "results/tables/overhead_table.hpp"

#include "results/analysis/evaluation_time.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb {

namespace {

std::string overhead_caption(const StudyIndex& index) {
    return std::string(
               "Wall time per evaluation: for each run, its wall-clock seconds (timings.csv) x 1e6 / the "
               "evaluations it spent; the median over the runs. This is COCO's measure (the total time of a "
               "run per evaluation, the evaluation and the bookkeeping included), not the optimiser's own "
               "time; random-search, where the study has it, is the floor: a uniform point per evaluation, "
               "the evaluation and the bookkeeping.") +
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
    Table t;
    t.id = "overhead";
    t.title = "Wall time per evaluation per problem and algorithm (microseconds)";
    t.header = {"Problem", "Dimension", "Algorithm", "Runs", "Median time per evaluation (us)"};
    for (const auto& e : times) {
        t.add_row({text_cell(e.problem), text_cell(std::to_string(e.dimension)),
                   text_cell(index.label(e.algorithm)), text_cell(std::to_string(e.runs)),
                   number_cell(e.median_microseconds, 3)});
    }
    t.caption = overhead_caption(index);
    t.latex_note = "Median over runs of wall seconds x 1e6 / evaluations; machine-dependent (Methods).";
    t.methods = {t.caption.substr(0, t.caption.size() - left_out_notes(index).size())};
    t.latex_column(0).heading = true;
    t.latex_column(2).key = true;
    format_columns(t);
    return t;
}

} // namespace mhb
