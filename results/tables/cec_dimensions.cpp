// The per-dimension errors, markers, mean errors and ranks of cec_dimensions.hpp.
#include "results/tables/cec_dimensions.hpp"

#include <algorithm>
#include <optional>

#include "results/analysis/dimension_budget.hpp"
#include "results/analysis/hypothesis_tests.hpp"
#include "results/analysis/statistics.hpp"
#include "results/tables/comparison_tables.hpp"

namespace mhb::tables {

namespace {

// The markers of every algorithm but the reference on one function, decided as the comparison
// tables decide theirs, but on the errors (so that errors below 1e-8 tie at 0).
void add_markers(std::map<std::string, Cell>& cells, const std::string& reference, bool paired,
                 std::int64_t max_fes, double alpha) {
    const auto ref = cells.find(reference);
    if (ref == cells.end())
        return;
    const Cell& y = ref->second;
    std::vector<Cell*> compared;
    std::vector<double> raw;
    std::vector<TestResult> tests;
    std::vector<std::size_t> nonzero;
    std::vector<double> a12;
    for (auto& [algorithm, cell] : cells) {
        if (algorithm == reference)
            continue;
        compared.push_back(&cell);
        a12.push_back(vargha_delaney_a12(cell.errors, y.errors));
        if (!paired) {
            tests.push_back(rank_sum_test(cell.errors, y.errors));
            nonzero.push_back(0);
        } else {
            const PairedValues pairs = paired_values(
                *cell.group, *y.group, [max_fes](const RunRecord& r) { return cec_error_at(r, max_fes); });
            std::size_t differing = 0;
            for (std::size_t i = 0; i < pairs.x.size(); ++i)
                differing += pairs.x[i] != pairs.y[i] ? 1U : 0U;
            tests.push_back(pairs.x.empty() ? TestResult{} : signed_rank_test(pairs.x, pairs.y));
            nonzero.push_back(differing);
        }
        raw.push_back(tests.back().p_value);
    }
    const std::vector<double> adjusted = holm_adjust(raw);
    for (std::size_t i = 0; i < compared.size(); ++i)
        compared[i]->marker = paired ? signed_rank_marker(adjusted[i], tests[i], nonzero[i], alpha)
                                     : comparison_marker(adjusted[i], a12[i], alpha);
}

} // namespace

std::vector<Dimension> by_dimension(const StudyIndex& index, const CecProtocol& protocol,
                                    const std::string& reference, double alpha) {
    std::vector<Dimension> out;
    for (const auto& p : cec_problems(index, protocol)) {
        if (out.empty() || out.back().dimension != p.dimension)
            out.push_back({p.dimension, {}, {}});
        std::map<std::string, Cell> cells;
        for (const auto& a : index.algorithms_on(p.problem)) {
            Cell cell;
            cell.group = index.find(p.problem, a);
            for (const auto* r : cell.group->runs) {
                const double error = cec_error_at(*r, p.max_fes);
                const std::int64_t termination = cec_termination_evaluations(*r, p.max_fes);
                cell.errors.push_back(error);
                cell.trials.push_back({error == 0.0 || termination < p.max_fes, termination, error});
            }
            cells[a] = std::move(cell);
        }
        add_markers(cells, reference, index.paired(p.problem), p.max_fes, alpha);
        out.back().functions.push_back(p);
        out.back().cells.push_back(std::move(cells));
    }
    return out;
}

std::string deviation_note(const CecProtocol& protocol, const Dimension& d) {
    std::size_t least = SIZE_MAX;
    std::size_t most = 0;
    for (const auto& cells : d.cells)
        for (const auto& [a, cell] : cells) {
            least = std::min(least, cell.errors.size());
            most = std::max(most, cell.errors.size());
        }
    std::int64_t max_fes = 0;
    for (const auto& f : d.functions)
        max_fes = std::max(max_fes, f.max_fes);
    const std::optional<std::int64_t> asked =
        DimensionEvaluations::parse(protocol.evaluations).at(d.dimension);
    std::string study;
    std::string protocol_asks;
    const auto runs = static_cast<std::size_t>(protocol.runs);
    if (most > 0 && (least != runs || most != runs)) {
        study +=
            (least == most ? std::to_string(most) : std::to_string(least) + " to " + std::to_string(most)) +
            " runs";
        protocol_asks += std::to_string(protocol.runs) + " runs";
    }
    if (!asked || *asked != max_fes) {
        study += (study.empty() ? "" : " and ") + std::string("MaxFES = ") + std::to_string(max_fes);
        protocol_asks +=
            (protocol_asks.empty() ? "" : " and ") +
            (asked ? "MaxFES = " + std::to_string(*asked)
                   : "no dimension " + std::to_string(d.dimension) + " (it sets MaxFES at " +
                         DimensionEvaluations::parse(protocol.evaluations).dimensions_text() + ")");
    }
    if (study.empty())
        return "";
    return " Not the protocol's size: this study has " + study + " at D = " + std::to_string(d.dimension) +
           ", the " + std::string(protocol.title) + " protocol asks for " + protocol_asks + ".";
}

MeanErrors mean_errors(const StudyIndex& index, const CecProtocol& protocol, const Dimension& d) {
    MeanErrors out;
    for (std::size_t f = 0; f < d.functions.size(); ++f) {
        if (d.functions[f].function == protocol.excluded_function) {
            ++out.excluded;
            continue;
        }
        std::vector<double> row;
        for (const auto& a : index.algorithms()) {
            const auto found = d.cells[f].find(a);
            if (found == d.cells[f].end() || found->second.errors.empty())
                break;
            row.push_back(mean(found->second.errors));
        }
        if (row.size() != index.algorithms().size()) {
            ++out.incomplete;
            continue;
        }
        out.functions.push_back(f);
        out.means.push_back(std::move(row));
    }
    return out;
}

std::vector<std::vector<double>> mean_error_ranks(const MeanErrors& m) {
    std::vector<std::vector<double>> ranks;
    for (const auto& row : m.means)
        ranks.push_back(average_ranks(row));
    return ranks;
}

} // namespace mhb::tables
