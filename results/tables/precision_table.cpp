#include "results/tables/precision_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "results/tables/table_cells.hpp"

namespace mhb {

namespace {

// A cell's compared values by run index, NaN for its failed runs (they hold their place).
std::vector<double> values_by_index(const RunGroup& group) {
    std::vector<double> values(group.runs.size() + group.failed, std::numeric_limits<double>::quiet_NaN());
    for (const RunRecord* r : group.runs)
        if (r->run_index >= 0 && static_cast<std::size_t>(r->run_index) < values.size())
            values[static_cast<std::size_t>(r->run_index)] = compared_value(*r);
    return values;
}

struct CellReading {
    std::string problem;
    std::string algorithm;
    std::int64_t runs = 0; // the cell's runs in the study
    CellPrecision point;   // where the rule stops (for the reference: where its partners do)
    bool reference = false;
    bool optimum_known = false;
};

std::vector<CellReading> read_cells(const StudyIndex& index, const PrecisionRule& rule) {
    std::vector<CellReading> cells;
    const std::string& reference = index.algorithms()[default_reference_index(index.algorithms())];
    for (const std::string& problem : index.problems()) {
        const RunGroup* ref_group = index.group(problem, reference);
        const std::vector<double> ref_values =
            ref_group ? values_by_index(*ref_group) : std::vector<double>{};
        const bool alone = index.algorithms().size() == 1;
        for (const std::string& algorithm : index.algorithms()) {
            const RunGroup* group = index.group(problem, algorithm);
            if (group == nullptr)
                continue;
            CellReading cell;
            cell.problem = problem;
            cell.algorithm = algorithm;
            cell.runs = static_cast<std::int64_t>(group->runs.size() + group->failed);
            cell.reference = algorithm == reference;
            cell.optimum_known = group->optimum_known();
            if (!cell.reference || alone)
                cell.point = stopping_point(values_by_index(*group), alone ? nullptr : &ref_values,
                                            index.paired(problem), rule);
            cells.push_back(std::move(cell));
        }
    }
    return cells;
}

std::string stop_text(const CellReading& cell, const PrecisionRule& rule) {
    if (cell.reference && cell.point.runs == 0)
        return "as many as its partners need";
    switch (cell.point.stop) {
    case PrecisionStop::precision_reached:
        return "precision reached";
    case PrecisionStop::max_reached:
        return "max-runs = " + std::to_string(rule.max) + " reached";
    case PrecisionStop::needs_runs:
        break;
    }
    return "unfinished: the rule asks for " + std::to_string(cell.point.runs) + " runs";
}

} // namespace

std::optional<Table> precision_table(const StudyIndex& index, const std::optional<PrecisionRule>& rule) {
    if (!rule || index.algorithms().empty())
        return std::nullopt;
    Table t;
    t.id = "runs_by_precision";
    t.title = "Runs by precision: the runs each cell took";
    t.header = {"Problem", "Algorithm", "Runs", "Standard error", "Stopped"};
    bool any_known = false;
    bool any_unknown = false;
    for (const CellReading& cell : read_cells(index, *rule)) {
        const bool shown = !cell.reference || index.algorithms().size() == 1;
        t.add_row({text_cell(cell.problem), text_cell(index.label(cell.algorithm)),
                   number_cell(static_cast<double>(cell.runs)),
                   shown ? number_cell(cell.point.standard_error, 2) : tables::empty_cell(),
                   text_cell(stop_text(cell, *rule))});
        (cell.optimum_known ? any_known : any_unknown) = true;
    }
    const std::string reference =
        index.label(index.algorithms()[default_reference_index(index.algorithms())]);
    t.caption = "Runs were added in rounds (" + std::to_string(rule->initial) + " to start, then " +
                std::to_string(rule->step) +
                " a round) until the standard error of a cell's mean difference to " + reference +
                " (paired by run where runs share seeds, Welch otherwise; of the mean alone in a "
                "study of one algorithm) was at most " +
                format_number(rule->precision, 3) + " on " +
                (any_known ? compared_scale(true) + (any_unknown ? " (f where f* is unknown)" : "")
                           : compared_scale(false)) +
                ", or max-runs = " + std::to_string(rule->max) + " was reached. " + reference +
                " ran as many runs as the cell that needed most; its row gives no error of its own.";
    t.latex_note = "Runs added in rounds until the standard error of the difference to " + reference +
                   " is at most " + format_number(rule->precision, 3) + ", at most " +
                   std::to_string(rule->max) + " runs.";
    format_columns(t);
    return t;
}

std::string precision_summary(const StudyIndex& index, const PrecisionRule& rule) {
    std::int64_t settled = 0;
    std::int64_t at_max = 0;
    std::int64_t least = std::numeric_limits<std::int64_t>::max();
    std::int64_t most = 0;
    const std::vector<CellReading> cells = read_cells(index, rule);
    for (const CellReading& cell : cells) {
        if (cell.reference && index.algorithms().size() > 1)
            continue;
        if (cell.point.stop == PrecisionStop::precision_reached) {
            ++settled;
            least = std::min(least, cell.runs);
            most = std::max(most, cell.runs);
        } else if (cell.point.stop == PrecisionStop::max_reached) {
            ++at_max;
        }
    }
    std::string line = "runs by precision (standard error <= " + format_number(rule.precision, 3) +
                       "): " + std::to_string(settled) + " of " + std::to_string(settled + at_max) +
                       " cells settled";
    if (settled > 0)
        line += " after " +
                (least == most ? std::to_string(most) : std::to_string(least) + "-" + std::to_string(most)) +
                " runs";
    if (at_max > 0)
        line += ", " + std::to_string(at_max) + " stopped at max-runs = " + std::to_string(rule.max);
    return line;
}

} // namespace mhb
