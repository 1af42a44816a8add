#include "runner/study/dry_run.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "problems/core/parameters.hpp" // format_real
#include "results/protocols/protocol_registry.hpp"
#include "results/store/study_files.hpp"
#include "runner/study/calibration.hpp"

namespace mhb {

namespace {

std::string count_text(double value) {
    char text[64];
    std::snprintf(text, sizeof text, value < 1e6 ? "%.0f" : "%.3g", value);
    return text;
}

std::string duration_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", seconds);
    return text;
}

// "cmaes 41%, lshade 30%, ...": each algorithm's share of the estimated time, largest first, so
// that a user sees which algorithm to leave out when the study is too long.
std::string algorithm_shares(const PreparedStudy& prepared, const StudyEstimate& estimate) {
    std::vector<std::size_t> order(prepared.algorithms.size());
    for (std::size_t a = 0; a < order.size(); ++a)
        order[a] = a;
    const auto& seconds = estimate.algorithm_seconds;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t i, std::size_t j) { return seconds[i] > seconds[j]; });
    const double total = std::max(estimate.cpu_seconds(), 1e-300);
    std::string out;
    for (const std::size_t a : order) {
        char share[16];
        std::snprintf(share, sizeof share, " %.0f%%", 100.0 * seconds[a] / total);
        out += (out.empty() ? "" : ", ") + prepared.algorithms[a].info.label + share;
    }
    return out;
}

// "1 problem", "3 problems".
std::string counted(std::size_t n, const char* noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

// "report: tables about 0.4 s; 21 figures (convergence 3, ...) about 3.2 s (PDF and PNG; this machine
// 1.1x the reference's time)".
std::string report_line(const ReportEstimate& estimate) {
    char text[96];
    std::snprintf(text, sizeof text, "report: tables about %.2g s", estimate.tables_seconds);
    std::string out = text;
    if (estimate.figures.empty())
        return out + "; figures not drawn (--no-figures)";
    std::string kinds;
    for (const auto& [kind, count] : estimate.figures)
        if (count > 0)
            kinds += (kinds.empty() ? "" : ", ") + kind + " " + std::to_string(count);
    std::snprintf(text, sizeof text, " about %.2g s (PDF and PNG; this machine %.2gx the reference's time)",
                  estimate.figures_seconds, estimate.speed_ratio);
    return out + "; " + counted(static_cast<std::size_t>(estimate.figure_count()), "figure") + " (" + kinds +
           ")" + text;
}

} // namespace

std::string dry_run_text(const PreparedStudy& prepared, const std::filesystem::path& dir, int threads,
                         bool report, bool figures) {
    std::ostringstream out;
    const Study& s = prepared.study;
    out << "mhbench run --dry-run: nothing is run or written.\n\n"
        << "study: " << counted(prepared.algorithms.size(), "algorithm") << " x "
        << counted(prepared.problems.size(), "problem") << " x " << counted(s.budgets.size(), "budget")
        << " x " << (s.by_precision ? "up to " : "") << counted(static_cast<std::size_t>(s.runs), "run")
        << " = " << (s.by_precision ? "at most " : "")
        << counted(static_cast<std::size_t>(prepared.run_count()), "run") << "; seed " << s.seed << ", seeds "
        << seed_mode_name(s.seeds)
        << (s.seeds == SeedMode::common ? " (every algorithm starts run r from the same stream)\n"
                                        : " (each algorithm its own streams)\n");
    if (const auto& rule = s.by_precision)
        out << "runs = auto: each cell starts with " << rule->initial << " runs and gets " << rule->step
            << " more a round until the standard error of its difference to the reference is at most "
            << format_real(rule->precision) << ", or it has " << rule->max
            << "; the estimates below are for the most, at least " << rule->initial << "/" << rule->max
            << " of them are needed\n";
    std::size_t width = 5;
    for (const auto& a : prepared.algorithms)
        width = std::max(width, a.info.label.size());
    out << "\nalgorithms (label, canonical spec):\n";
    for (const auto& a : prepared.algorithms)
        out << "  " << a.info.label << std::string(width - a.info.label.size() + 2, ' ') << a.info.spec
            << '\n';
    out << "\nproblems (" << prepared.problems.size() << "):\n";
    const std::size_t shown = prepared.problems.size() > 12 ? 10 : prepared.problems.size();
    for (std::size_t p = 0; p < shown; ++p)
        out << "  " << prepared.problems[p].spec << '\n';
    if (shown < prepared.problems.size())
        out << "  ... and " << prepared.problems.size() - shown << " more, to "
            << prepared.problems.back().spec << '\n';
    const StudyEstimate estimate = estimate_study(prepared, threads);
    out << "\nbudgets:\n";
    for (std::size_t b = 0; b < s.budgets.size(); ++b) {
        const auto& e = estimate.budgets[b];
        out << "  " << prepared.budget_texts[b] << ": " << (e.exact ? "" : "about ")
            << count_text(e.evaluations) << " evaluations";
        if (s.budgets[b].evaluations_by_dimension) { // what a run gets at each dimension of the study
            // Each D with its first problem, whose budget says the count.
            std::map<std::int64_t, std::size_t> dimensions;
            for (std::size_t p = 0; p < prepared.problems.size(); ++p)
                dimensions.emplace(prepared.problems[p].problem->dimension(), p);
            out << " (per run:";
            for (const auto& [d, p] : dimensions)
                out << (d == dimensions.begin()->first ? " " : ", ")
                    << count_text(static_cast<double>(*prepared.budget_for(b, p).max_evaluations))
                    << " at D = " << d;
            out << ")";
        }
        out << '\n';
    }
    for (const SuiteProtocol* protocol : protocols_in_force(s.protocol))
        if (const std::string line = protocol->dry_run_line(); !line.empty())
            out << '\n' << line << '\n';
    const double run_seconds = estimate.cpu_seconds() / std::max(threads, 1);
    const ReportEstimate after = estimate_report(prepared, figures);
    const double report_seconds = report ? after.seconds() : 0.0;
    if (report)
        out << '\n' << report_line(after) << '\n';
    char line[200];
    std::snprintf(line, sizeof line, "%s evaluations, roughly %.3g s on %d thread%s (runs %.3g s%s)",
                  count_text(estimate.evaluations()).c_str(), run_seconds + report_seconds, threads,
                  threads == 1 ? "" : "s", run_seconds, report ? ", then the report" : "");
    out << "\ntotal: " << line << " (runs calibrated on " << estimate.calibration_runs << " short runs, "
        << duration_text(estimate.calibration_seconds) << ")\n";
    if (prepared.algorithms.size() > 1)
        out << "time by algorithm: " << algorithm_shares(prepared, estimate) << '\n';
    out << "output: " << dir.string();
    if (std::filesystem::exists(dir / StudyFiles::store))
        out << " (holds a study store: runs of this study found in it are not run again)\n";
    else if (std::filesystem::exists(dir / StudyFiles::runs) ||
             std::filesystem::exists(dir / StudyFiles::journal))
        out << " (holds a study of an earlier mhbench: the run needs --overwrite or another --out)\n";
    else
        out << '\n';
    return out.str();
}

} // namespace mhb
