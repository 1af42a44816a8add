// The competition's tables of a study that follows a CEC protocol (cec_tables.hpp): per dimension
// the errors and the ranks, and the CEC 2017 score over the dimensions.
#include "results/tables/cec_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>

#include "results/analysis/hypothesis_tests.hpp"
#include "results/analysis/statistics.hpp"
#include "results/tables/cec_dimensions.hpp"
#include "results/tables/comparison_tables.hpp"
#include "results/tables/table_cells.hpp"

namespace mhb::tables {
namespace {

// The CEC 2017 score's weight of each dimension (TR section 2.3).
const std::map<std::int64_t, double>& score_weights() {
    static const std::map<std::int64_t, double> weights = {{10, 0.1}, {30, 0.2}, {50, 0.3}, {100, 0.4}};
    return weights;
}

std::string function_name(int number) {
    // Appended, not "F" + ...: GCC 12 warns falsely (-Wrestrict) of that once inlined.
    std::string name = "F";
    return name.append(std::to_string(number));
}

const MarkerTestsWording cec_tests_wording = {
    .paired = "two-sided Wilcoxon signed-rank test of the paired differences (runs paired by seed)",
    .paired_where = " where runs pair, ",
    .unpaired = "two-sided Wilcoxon rank-sum test (Mann-Whitney U)",
    .unpaired_where = " elsewhere",
    .none = "none (no function has runs of the reference and another algorithm)"};

std::string reference_text(const StudyIndex& index, const std::string& reference, double alpha,
                           bool paired_any, bool unpaired_any) {
    return "Markers against the reference " + index.label(reference) + ": " +
           marker_tests_text(paired_any, unpaired_any, cec_tests_wording) +
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
    const std::size_t vs_reference_column = 7;
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
        t.add_footer(win_tie_loss_row(t.header.size(), index.label(a), vs_reference_column, found->second));
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
    t.latex_column(vs_reference_column).header = "vs ref.";
    format_columns(t);
    return t;
}

// Each algorithm's sum over the ranked functions of its rank and, for CEC 2022, of its U-score.
struct RankTotals {
    std::vector<double> rank_sum;
    std::vector<double> u_score; // zeros where the protocol has no termination row
};

RankTotals rank_totals(const StudyIndex& index, const CecProtocol& protocol, const Dimension& d,
                       const MeanErrors& m) {
    const auto& algorithms = index.algorithms();
    RankTotals totals{std::vector<double>(algorithms.size(), 0.0),
                      std::vector<double>(algorithms.size(), 0.0)};
    for (const auto& row : mean_error_ranks(m))
        for (std::size_t j = 0; j < row.size(); ++j)
            totals.rank_sum[j] += row[j];
    if (protocol.termination_row)
        for (const std::size_t f : m.functions) {
            std::vector<std::vector<CecTrial>> trials;
            for (const auto& a : algorithms)
                trials.push_back(d.cells[f].at(a).trials);
            const auto scores = cec_u_scores(trials);
            for (std::size_t j = 0; j < algorithms.size(); ++j)
                totals.u_score[j] += scores[j];
        }
    return totals;
}

// An algorithm's markers against the reference over the dimension's functions.
std::vector<std::string> markers_of(const Dimension& d, const std::string& algorithm) {
    std::vector<std::string> markers;
    for (std::size_t f = 0; f < d.functions.size(); ++f)
        if (const auto found = d.cells[f].find(algorithm);
            found != d.cells[f].end() && !found->second.marker.empty())
            markers.push_back(found->second.marker);
    return markers;
}

// A row per algorithm over `n` ranked functions; the lowest rank and the highest U-score in bold.
void add_rank_rows(Table& t, const StudyIndex& index, const CecProtocol& protocol, const Dimension& d,
                   const std::string& reference, const RankTotals& totals, std::size_t n) {
    const auto& algorithms = index.algorithms();
    double best_rank = INFINITY;
    for (const double r : totals.rank_sum)
        best_rank = std::min(best_rank, r);
    double best_u = -std::numeric_limits<double>::infinity();
    for (const double u : totals.u_score)
        best_u = std::max(best_u, u);
    for (std::size_t j = 0; j < algorithms.size(); ++j) {
        const std::vector<std::string> markers = markers_of(d, algorithms[j]);
        const bool is_reference = algorithms[j] == reference;
        TableCell mean_rank = number_cell(n == 0 ? NAN : totals.rank_sum[j] / static_cast<double>(n), 4);
        mean_rank.bold = n > 0 && totals.rank_sum[j] == best_rank;
        std::vector<TableCell> row = {
            text_cell(index.label(algorithms[j]) + (is_reference ? " (reference)" : "")), mean_rank,
            number_cell(n == 0 ? NAN : totals.rank_sum[j], 5),
            text_cell(is_reference || markers.empty() ? "" : win_tie_loss(markers))};
        if (protocol.termination_row) {
            TableCell u = number_cell(n == 0 ? NAN : totals.u_score[j], 6);
            u.bold = n > 0 && totals.u_score[j] == best_u;
            row.push_back(u);
        }
        t.add_row(std::move(row));
    }
}

// The Friedman test of the ranks as a sentence, when there are two functions and two algorithms.
std::string friedman_note(const MeanErrors& m, std::size_t algorithms) {
    const std::size_t n = m.functions.size();
    if (n < 2 || algorithms < 2)
        return "";
    const FriedmanResult result = friedman_test(m.means);
    return " Friedman test of the ranks over the " + std::to_string(n) +
           " functions: chi-square = " + format_number(result.chi_square, 5) +
           ", df = " + format_number(result.degrees_of_freedom) +
           ", p = " + format_number(result.p_value, 3) + ".";
}

std::string ranks_caption(const StudyIndex& index, const CecProtocol& protocol, const Dimension& d,
                          const MeanErrors& m) {
    const std::size_t left_out = m.incomplete;
    return "Per function, the algorithms are ranked by their mean error after MaxFES (an error below 1e-8 is "
           "0; "
           "rank 1 = the lowest mean, ties share the mean of their ranks), as the " +
           std::string(protocol.title) +
           " protocol ranks entries; mean and sum over the functions, the lowest in bold." +
           friedman_note(m, index.algorithms().size()) +
           (left_out == 0
                ? std::string()
                : " " + std::to_string(left_out) + (left_out == 1 ? " function is" : " functions are") +
                      " left out: some algorithm has no successful run on it.") +
           (m.excluded == 0 ? std::string()
                            : " F" + std::to_string(protocol.excluded_function) +
                                  ", which the organisers excluded from the competition, is not ranked.") +
           " w/t/l: the functions on which the algorithm is significantly better than, not different from "
           "and "
           "worse than the reference (the markers of cec_errors_d" +
           std::to_string(d.dimension) + ")." +
           (protocol.termination_row
                ? " U-score (the CEC 2022 criterion, TR section 2.3): on each function every trial of every "
                  "algorithm is ranked, those that reached an error below 1e-8 by the evaluations they took "
                  "(FEterm), ahead of the others by their error, the best trial ranked highest (ties share "
                  "the "
                  "mean rank); an algorithm scores the sum of its trials' ranks minus n(n + 1)/2, summed "
                  "over "
                  "the functions; the highest in bold."
                : std::string()) +
           deviation_note(protocol, d) + left_out_notes(index);
}

Table ranks_table(const StudyIndex& index, const CecProtocol& protocol, const Dimension& d,
                  const std::string& reference) {
    const MeanErrors m = mean_errors(index, protocol, d);
    const std::size_t n = m.functions.size();
    Table t;
    const std::string dim = std::to_string(d.dimension);
    t.id = "cec_ranks_d" + dim;
    t.title = std::string(protocol.title) + ", D = " + dim + ": ranks of the mean errors over " +
              std::to_string(n) + (n == 1 ? " function" : " functions");
    t.header = {"Algorithm", "Mean rank", "Sum of ranks", "w/t/l vs reference"};
    if (protocol.termination_row)
        t.header.emplace_back("U-score");
    add_rank_rows(t, index, protocol, d, reference, rank_totals(index, protocol, d, m), n);
    t.caption = ranks_caption(index, protocol, d, m);
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
} // namespace mhb::tables

namespace mhb {

std::vector<Table> cec_tables(const StudyIndex& index, const CecProtocol& protocol,
                              const std::string& reference, double alpha) {
    std::vector<Table> out;
    const std::vector<tables::Dimension> dimensions = tables::by_dimension(index, protocol, reference, alpha);
    for (const auto& d : dimensions) {
        out.push_back(tables::errors_table(index, protocol, d, reference, alpha));
        out.push_back(tables::ranks_table(index, protocol, d, reference));
    }
    if (protocol.name == "cec2017")
        if (auto score = tables::score_table(index, protocol, dimensions))
            out.push_back(std::move(*score));
    return out;
}

} // namespace mhb
