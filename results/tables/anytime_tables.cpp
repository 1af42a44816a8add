#include "results/tables/anytime_tables.hpp"

#include <algorithm>
#include <cmath>

#include "results/analysis/curve_data.hpp" // ecdf_target_gaps: the figure's targets
#include "results/analysis/ecdf_area.hpp"
#include "results/analysis/ert_bootstrap.hpp"
#include "results/analysis/evaluation_counts.hpp"
#include "results/store/csv.hpp" // csv_number: the seed text of a target
#include "results/tables/table_cells.hpp"

namespace mhb {

namespace {

std::string ecdf_area_caption(const StudyIndex& index) {
    return "Area under the ECDF of targets (AUC), as IOHanalyzer's runtime ECDF defines it: the fraction of "
           "(run, target) pairs whose best-so-far reached f - f* <= target by t evaluations, integrated over "
           "log10 t from 1 to B and divided by log10 B, so that 1 means every target at the first "
           "evaluation and 0 none within B. Targets: f - f* = 1e2, 1e1, ..., 1e-8 (COCO's; those of "
           "target_hits.csv and the fixed-target ECDF figure). B: the problem's evaluation count E (the "
           "study's evaluation budget, else the largest count any run on the problem spent). Computed "
           "exactly from each run's improvements (IOHanalyzer integrates trapezoids on 50 budgets). "
           "Reached: pairs reached within B, of all pairs (runs x 11 targets). All problems: the mean of the "
           "problems' areas, each problem weighing the same; only problems with a known f*." +
           left_out_notes(index);
}

} // namespace

std::optional<Table> ecdf_area_table(const StudyIndex& index) {
    const std::vector<EcdfAreaGroup> groups = ecdf_areas(index);
    if (groups.empty())
        return std::nullopt;
    Table t;
    t.id = "ecdf_area";
    t.title = "Area under the ECDF of targets (log-scaled evaluations) per problem and algorithm";
    t.header = {"Problem", "B (evaluations)", "Algorithm", "Runs", "Reached", "AUC"};
    for (const auto& group : groups) {
        double best = -1.0;
        for (const auto& c : group.cells)
            best = std::max(best, c.area);
        for (const auto& c : group.cells) {
            TableCell area = fixed_cell(c.area, 3);
            area.bold = c.area == best;
            t.add_row({text_cell(group.problem.empty() ? "all " + std::to_string(group.problems) + " problems"
                                                       : group.problem),
                       group.problem.empty() ? text_cell("each its own")
                                             : number_cell(static_cast<double>(group.budget), 6),
                       text_cell(index.label(c.algorithm)), text_cell(std::to_string(c.runs)),
                       text_cell(std::to_string(c.reached) + "/" + std::to_string(c.pairs)),
                       std::move(area)});
        }
    }
    t.caption = ecdf_area_caption(index);
    t.latex_note = "AUC: area under the ECDF of (run, target) pairs, targets f - f* = 1e2 ... 1e-8, over "
                   "log10 evaluations from 1 to B, divided by log10 B (Methods).";
    t.methods = {t.caption.substr(0, t.caption.size() - left_out_notes(index).size())};
    t.latex_column(0).heading = true;
    t.latex_column(2).key = true;
    format_columns(t);
    return t;
}

namespace {

// A target as the figures name it: "1e2", "1e-8" (the gaps are powers of ten); its exact value in CSV.
TableCell target_cell(double gap) {
    const std::string exponent = std::to_string(std::lround(std::log10(gap)));
    TableCell cell = text_cell("1e" + exponent);
    cell.value = csv_number(gap);
    cell.latex = "$10^{" + exponent + "}$";
    return cell;
}

// The seed of one bootstrap: a function of what it is about, never of the order of the table.
std::uint64_t ert_seed(const std::string& problem, const std::string& algorithm, double gap) {
    return mix64(stable_hash("ert bootstrap\n" + problem + "\n" + algorithm + "\n" + csv_number(gap)));
}

std::vector<TargetHit> target_hits_of(const RunGroup& g, double gap) {
    std::vector<TargetHit> hits;
    for (const RunRecord* r : g.runs) {
        const double f_opt = *r->f_opt;
        const auto hit = first_evaluation_reaching(*r, [&](double f) { return f - f_opt <= gap; });
        hits.push_back({hit.has_value(), hit.value_or(r->evaluations)});
    }
    return hits;
}

bool any_success(const std::vector<TargetHit>& hits) {
    return std::any_of(hits.begin(), hits.end(), [](const TargetHit& h) { return h.success; });
}

// The rows of one problem: the targets some run on it reached, each algorithm's ERT.
void add_ert_rows(Table& t, const StudyIndex& index, const std::string& problem) {
    std::vector<const RunGroup*> groups;
    for (const auto& a : index.algorithms_on(problem))
        if (const RunGroup* g = index.find(problem, a); g != nullptr && g->runs.front()->f_opt)
            groups.push_back(g);
    for (const double gap : ecdf_target_gaps()) {
        std::vector<std::vector<TargetHit>> hits;
        bool reached = false;
        for (const RunGroup* g : groups) {
            hits.push_back(target_hits_of(*g, gap));
            reached = reached || any_success(hits.back());
        }
        if (!reached)
            continue;
        for (std::size_t k = 0; k < groups.size(); ++k) {
            Rng rng(ert_seed(problem, groups[k]->algorithm, gap));
            const std::optional<ErtInterval> ert = ert_interval(hits[k], rng);
            std::size_t successes = 0;
            for (const auto& h : hits[k])
                successes += h.success ? 1U : 0U;
            t.add_row({text_cell(problem), target_cell(gap), text_cell(index.label(groups[k]->algorithm)),
                       text_cell(std::to_string(successes) + "/" + std::to_string(hits[k].size())),
                       number_cell(ert ? ert->ert : INFINITY, 4),
                       ert ? number_cell(ert->p10, 4) : tables::empty_cell(),
                       ert ? number_cell(ert->p90, 4) : tables::empty_cell()});
        }
    }
}

std::string ert_caption(const StudyIndex& index) {
    return "ERT to each target f - f* of the fixed-target ECDF (1e2 ... 1e-8) that some run on the problem "
           "reached, as COCO defines it: evaluations of all runs (to the target for successful ones, all "
           "they spent otherwise) / successful runs; inf when none succeeded. Each hit is the first "
           "evaluation at which the run's best-so-far reached the target, from its improvements. 10% and "
           "90%: COCO's dispersion of the ERT (cocopp toolsstats.drawSP), the percentiles (cocopp's "
           "prctile) of " +
           std::to_string(ert_bootstrap_samples) +
           " simulated restarts: runs drawn uniformly with replacement, summing the evaluations of "
           "unsuccessful ones until a successful one is drawn; its draws come from an mhb::Rng seeded "
           "by the problem, algorithm and target, so the table is the same each time it is made." +
           left_out_notes(index);
}

} // namespace

std::optional<Table> ert_table(const StudyIndex& index) {
    Table t;
    t.id = "ert";
    t.title = "ERT per target with bootstrap percentiles of simulated restarts";
    t.header = {"Problem", "Target f - f*", "Algorithm", "Successes", "ERT", "ERT 10%", "ERT 90%"};
    for (const auto& problem : index.problems())
        add_ert_rows(t, index, problem);
    if (t.rows.empty())
        return std::nullopt;
    t.caption = ert_caption(index);
    t.latex_note = "ERT (COCO) per target; 10% and 90%: percentiles of " +
                   std::to_string(ert_bootstrap_samples) + " bootstrapped simulated restarts (Methods).";
    t.methods = {t.caption.substr(0, t.caption.size() - left_out_notes(index).size())};
    t.latex_column(0).heading = true;
    t.latex_column(1).key = true;
    t.latex_column(2).key = true;
    format_columns(t);
    return t;
}

} // namespace mhb
