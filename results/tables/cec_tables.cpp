#include "results/tables/cec_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "results/analysis/dimension_budget.hpp"
#include "results/analysis/hypothesis_tests.hpp"
#include "results/analysis/statistics.hpp"
#include "results/tables/comparison_tables.hpp"

namespace mhb {
namespace {

// One algorithm on one function: its runs, their errors after MaxFES, its trials as CEC 2022 ranks
// them, and its marker against the reference ("" for the reference and where no test ran).
struct Cell {
    const RunGroup* group = nullptr;
    std::vector<double> errors; // in the order of group->runs
    std::vector<CecTrial> trials;
    std::string marker;
};

// One dimension: its functions (problems, by number) and each function's cells by algorithm spec.
struct Dimension {
    std::int64_t dimension = 0;
    std::vector<CecProblem> functions;
    std::vector<std::map<std::string, Cell>> cells;
};

// The CEC 2017 score's weight of each dimension (TR section 2.3).
const std::map<std::int64_t, double>& score_weights() {
    static const std::map<std::int64_t, double> weights = {{10, 0.1}, {30, 0.2}, {50, 0.3}, {100, 0.4}};
    return weights;
}

std::string function_name(int number) {
    return std::string("F") + std::to_string(number);
}

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

// How the study departs from the protocol at this dimension, as a sentence ("" when it does not).
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

std::string reference_text(const StudyIndex& index, const std::string& reference, double alpha,
                           bool paired_any, bool unpaired_any) {
    std::string tests;
    if (paired_any)
        tests = "two-sided Wilcoxon signed-rank test of the paired differences (runs paired by seed)";
    if (paired_any && unpaired_any)
        tests += " where runs pair, ";
    if (unpaired_any)
        tests += "two-sided Wilcoxon rank-sum test (Mann-Whitney U)";
    if (paired_any && unpaired_any)
        tests += " elsewhere";
    if (tests.empty())
        tests = "none (no function has runs of the reference and another algorithm)";
    return "Markers against the reference " + index.label(reference) + ": " + tests +
           " of the errors, Holm correction across each function's comparisons, alpha = " +
           format_number(alpha, 3) + "; + better, - worse, = no significant difference.";
}

Table errors_table(const StudyIndex& index, const CecProtocol& protocol, const Dimension& d,
                   const std::string& reference, double alpha) {
    Table t;
    const std::string dim = std::to_string(d.dimension);
    t.id = "cec_errors_d" + dim;
    const std::int64_t max_fes = d.functions.front().max_fes;
    t.title = std::string(protocol.title) + ", D = " + dim +
              ": error f - f* after MaxFES = " + std::to_string(max_fes) + " evaluations";
    t.header = {"Function", "Algorithm", "Best", "Worst", "Median", "Mean", "Std", "vs reference"};
    std::map<std::string, std::vector<std::string>> markers;
    bool paired_any = false;
    bool unpaired_any = false;
    for (std::size_t f = 0; f < d.functions.size(); ++f) {
        const CecProblem& p = d.functions[f];
        const bool compared = d.cells[f].count(reference) != 0 && d.cells[f].size() > 1;
        paired_any = paired_any || (compared && index.paired(p.problem));
        unpaired_any = unpaired_any || (compared && !index.paired(p.problem));
        for (const auto& a : index.algorithms()) {
            const auto found = d.cells[f].find(a);
            if (found == d.cells[f].end())
                continue;
            const Cell& cell = found->second;
            const Summary s = summarize(cell.errors);
            t.add_row({text_cell(function_name(p.function)), text_cell(index.label(a)),
                       number_cell(s.best, 3), number_cell(s.worst, 3), number_cell(s.median, 3),
                       number_cell(s.mean, 3), number_cell(s.std, 3), marker_cell(cell.marker)});
            if (!cell.marker.empty())
                markers[a].push_back(cell.marker);
        }
    }
    for (const auto& a : index.algorithms()) {
        const auto found = markers.find(a);
        if (found == markers.end())
            continue;
        std::vector<TableCell> row(t.header.size(), text_cell(""));
        row[0] = text_cell("w/t/l");
        row[1] = text_cell(index.label(a));
        row[7] = text_cell(win_tie_loss(found->second));
        t.add_footer(std::move(row));
    }
    std::string sizes;
    bool same_max_fes = true;
    for (const auto& p : d.functions)
        same_max_fes = same_max_fes && p.max_fes == max_fes;
    if (!same_max_fes)
        sizes =
            " MaxFES differs between functions here (the budget gives no evaluation count; each function's "
            "is the most any run on it spent): the title names the first.";
    t.caption =
        "The error f - f* of each run's best-so-far after MaxFES evaluations, over its runs (an error "
        "below 1e-8 is 0, as the " +
        std::string(protocol.title) + " protocol takes it); Std is the sample standard deviation. " +
        reference_text(index, reference, alpha, paired_any, unpaired_any) +
        (markers.empty() ? std::string()
                         : " Rows under the rule: w/t/l, the functions on which the algorithm is "
                           "significantly better than the reference (+), not significantly different "
                           "(=) and significantly worse (-).") +
        sizes + deviation_note(protocol, d) + left_out_notes(index);
    t.latex_column(0).heading = true; // the function heads its rows
    t.latex_column(1).key = true;
    t.latex_column(7).header = "vs ref.";
    format_columns(t);
    return t;
}

// Per function (row) each algorithm's (column) mean error, on the functions the protocol ranks
// (not CEC 2017's F2) where every algorithm has runs.
struct MeanErrors {
    std::vector<std::size_t> functions;     // indices into Dimension::functions
    std::vector<std::vector<double>> means; // [function][algorithm]
    std::size_t excluded = 0;               // functions of the protocol's excluded one (F2 of 2017)
    std::size_t incomplete = 0;             // functions on which some algorithm has no successful run
};

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

// The rank (1 = lowest) of each algorithm's mean error on each function of `m`.
std::vector<std::vector<double>> mean_error_ranks(const MeanErrors& m) {
    std::vector<std::vector<double>> ranks;
    for (const auto& row : m.means)
        ranks.push_back(average_ranks(row));
    return ranks;
}

Table ranks_table(const StudyIndex& index, const CecProtocol& protocol, const Dimension& d,
                  const std::string& reference) {
    const auto& algorithms = index.algorithms();
    const MeanErrors m = mean_errors(index, protocol, d);
    const auto ranks = mean_error_ranks(m);
    const std::size_t n = m.functions.size();
    std::vector<double> rank_sum(algorithms.size(), 0.0);
    for (const auto& row : ranks)
        for (std::size_t j = 0; j < row.size(); ++j)
            rank_sum[j] += row[j];
    std::vector<double> u_score(algorithms.size(), 0.0);
    if (protocol.termination_row)
        for (const std::size_t f : m.functions) {
            std::vector<std::vector<CecTrial>> trials;
            for (const auto& a : algorithms)
                trials.push_back(d.cells[f].at(a).trials);
            const auto scores = cec_u_scores(trials);
            for (std::size_t j = 0; j < algorithms.size(); ++j)
                u_score[j] += scores[j];
        }

    Table t;
    const std::string dim = std::to_string(d.dimension);
    t.id = "cec_ranks_d" + dim;
    t.title = std::string(protocol.title) + ", D = " + dim + ": ranks of the mean errors over " +
              std::to_string(n) + (n == 1 ? " function" : " functions");
    t.header = {"Algorithm", "Mean rank", "Sum of ranks", "w/t/l vs reference"};
    if (protocol.termination_row)
        t.header.emplace_back("U-score");
    double best_rank = INFINITY;
    for (const double r : rank_sum)
        best_rank = std::min(best_rank, r);
    double best_u = -INFINITY;
    for (const double u : u_score)
        best_u = std::max(best_u, u);
    for (std::size_t j = 0; j < algorithms.size(); ++j) {
        std::vector<std::string> markers;
        for (std::size_t f = 0; f < d.functions.size(); ++f)
            if (const auto found = d.cells[f].find(algorithms[j]);
                found != d.cells[f].end() && !found->second.marker.empty())
                markers.push_back(found->second.marker);
        const bool is_reference = algorithms[j] == reference;
        TableCell mean_rank = number_cell(n == 0 ? NAN : rank_sum[j] / static_cast<double>(n), 4);
        mean_rank.bold = n > 0 && rank_sum[j] == best_rank;
        std::vector<TableCell> row = {
            text_cell(index.label(algorithms[j]) + (is_reference ? " (reference)" : "")), mean_rank,
            number_cell(n == 0 ? NAN : rank_sum[j], 5),
            text_cell(is_reference || markers.empty() ? "" : win_tie_loss(markers))};
        if (protocol.termination_row) {
            TableCell u = number_cell(n == 0 ? NAN : u_score[j], 6);
            u.bold = n > 0 && u_score[j] == best_u;
            row.push_back(u);
        }
        t.add_row(std::move(row));
    }
    std::string friedman;
    if (n >= 2 && algorithms.size() >= 2) {
        const FriedmanResult result = friedman_test(m.means);
        friedman = " Friedman test of the ranks over the " + std::to_string(n) +
                   " functions: chi-square = " + format_number(result.chi_square, 5) +
                   ", df = " + format_number(result.degrees_of_freedom) +
                   ", p = " + format_number(result.p_value, 3) + ".";
    }
    const std::size_t left_out = m.incomplete;
    t.caption =
        "Per function, the algorithms are ranked by their mean error after MaxFES (an error below 1e-8 is 0; "
        "rank 1 = the lowest mean, ties share the mean of their ranks), as the " +
        std::string(protocol.title) +
        " protocol ranks entries; mean and sum over the functions, the lowest in bold." + friedman +
        (left_out == 0
             ? std::string()
             : " " + std::to_string(left_out) + (left_out == 1 ? " function is" : " functions are") +
                   " left out: some algorithm has no successful run on it.") +
        (m.excluded == 0 ? std::string()
                         : " F" + std::to_string(protocol.excluded_function) +
                               ", which the organisers excluded from the competition, is not ranked.") +
        " w/t/l: the functions on which the algorithm is significantly better than, not different from and "
        "worse than the reference (the markers of cec_errors_d" +
        dim + ")." +
        (protocol.termination_row
             ? " U-score (the CEC 2022 criterion, TR section 2.3): on each function every trial of every "
               "algorithm is ranked, those that reached an error below 1e-8 by the evaluations they took "
               "(FEterm), ahead of the others by their error, the best trial ranked highest (ties share the "
               "mean rank); an algorithm scores the sum of its trials' ranks minus n(n + 1)/2, summed over "
               "the functions; the highest in bold."
             : std::string()) +
        deviation_note(protocol, d) + left_out_notes(index);
    format_columns(t);
    return t;
}

// The CEC 2017 score over D = 10, 30, 50, 100 (TR section 2.3), when all four are there.
std::optional<Table> score_table(const StudyIndex& index, const CecProtocol& protocol,
                                 const std::vector<Dimension>& dimensions) {
    const auto& algorithms = index.algorithms();
    std::vector<double> se(algorithms.size(), 0.0);
    std::vector<double> sr(algorithms.size(), 0.0);
    std::size_t found = 0;
    bool excluded = false;
    std::string functions;
    for (const auto& d : dimensions) {
        const auto weight = score_weights().find(d.dimension);
        if (weight == score_weights().end())
            continue;
        ++found;
        const MeanErrors m = mean_errors(index, protocol, d);
        const auto ranks = mean_error_ranks(m);
        excluded = excluded || m.excluded > 0;
        for (std::size_t f = 0; f < m.means.size(); ++f)
            for (std::size_t j = 0; j < algorithms.size(); ++j) {
                se[j] += weight->second * m.means[f][j];
                sr[j] += weight->second * ranks[f][j];
            }
        functions += (functions.empty() ? "" : ", ") + std::to_string(m.functions.size()) +
                     " at D = " + std::to_string(d.dimension);
    }
    if (found != score_weights().size() || algorithms.size() < 2)
        return std::nullopt;
    const double se_min = *std::min_element(se.begin(), se.end());
    const double sr_min = *std::min_element(sr.begin(), sr.end());
    // 50 (1 - (S - S_min) / S) = 50 S_min / S; 50 when S = 0 (no error anywhere: the best possible).
    const auto part = [](double s, double s_min) { return s == 0.0 ? 50.0 : 50.0 * (1.0 - (s - s_min) / s); };
    Table t;
    t.id = "cec2017_score";
    t.title = "CEC 2017 score over D = 10, 30, 50 and 100";
    t.header = {"Algorithm", "SE", "Score1", "SR", "Score2", "Score"};
    std::vector<double> total(algorithms.size());
    for (std::size_t j = 0; j < algorithms.size(); ++j)
        total[j] = part(se[j], se_min) + part(sr[j], sr_min);
    const double best = *std::max_element(total.begin(), total.end());
    for (std::size_t j = 0; j < algorithms.size(); ++j) {
        TableCell score = number_cell(total[j], 5);
        score.bold = total[j] == best;
        t.add_row({text_cell(index.label(algorithms[j])), number_cell(se[j], 5),
                   number_cell(part(se[j], se_min), 5), number_cell(sr[j], 5),
                   number_cell(part(sr[j], sr_min), 5), score});
    }
    t.caption =
        "The competition's score (CEC 2017 TR, section 2.3): SE = the sum over the functions of the mean "
        "error after MaxFES (below 1e-8: 0), weighted 0.1, 0.2, 0.3 and 0.4 at D = 10, 30, 50 and 100; "
        "Score1 = 50 (1 - (SE - SE_min) / SE). SR = the same sum of the ranks of the mean errors among "
        "the algorithms (rank 1 = the lowest), Score2 = 50 (1 - (SR - SR_min) / SR). Score = Score1 + "
        "Score2, at most 100; the highest in bold. Functions with runs of every algorithm: " +
        functions + "." +
        (excluded ? " F" + std::to_string(protocol.excluded_function) +
                        ", which the organisers excluded from the competition, is not scored."
                  : std::string()) +
        left_out_notes(index);
    format_columns(t);
    return t;
}

} // namespace

std::vector<double> cec_u_scores(const std::vector<std::vector<CecTrial>>& trials) {
    // Every trial, worst first: not reached before reached; among those not reached, the larger error
    // first; among those reached, the later FEterm first. Rank 1 = the worst, so the best trial gets
    // the highest rank (n m when no trial failed), as the TR assigns them.
    struct Entry {
        std::size_t algorithm;
        const CecTrial* trial;
    };
    std::vector<Entry> all;
    for (std::size_t j = 0; j < trials.size(); ++j)
        for (const auto& t : trials[j])
            all.push_back({j, &t});
    const auto worse = [](const CecTrial& a, const CecTrial& b) { // a ranks below b
        if (a.reached != b.reached)
            return !a.reached;
        if (!a.reached)
            return a.error > b.error;
        return a.termination > b.termination;
    };
    std::stable_sort(all.begin(), all.end(),
                     [&](const Entry& a, const Entry& b) { return worse(*a.trial, *b.trial); });
    std::vector<double> scores(trials.size(), 0.0);
    for (std::size_t i = 0; i < all.size();) {
        std::size_t end = i + 1;
        while (end < all.size() && !worse(*all[i].trial, *all[end].trial))
            ++end;
        const double rank = (static_cast<double>(i + 1) + static_cast<double>(end)) / 2.0; // ties: mean rank
        for (std::size_t k = i; k < end; ++k)
            scores[all[k].algorithm] += rank;
        i = end;
    }
    for (std::size_t j = 0; j < trials.size(); ++j) {
        const auto n = static_cast<double>(trials[j].size());
        scores[j] -= n * (n + 1.0) / 2.0;
    }
    return scores;
}

std::vector<Table> cec_tables(const StudyIndex& index, const CecProtocol& protocol,
                              const std::string& reference, double alpha) {
    std::vector<Table> tables;
    const std::vector<Dimension> dimensions = by_dimension(index, protocol, reference, alpha);
    for (const auto& d : dimensions) {
        tables.push_back(errors_table(index, protocol, d, reference, alpha));
        tables.push_back(ranks_table(index, protocol, d, reference));
    }
    if (protocol.name == "cec2017")
        if (auto score = score_table(index, protocol, dimensions))
            tables.push_back(std::move(*score));
    return tables;
}

} // namespace mhb
