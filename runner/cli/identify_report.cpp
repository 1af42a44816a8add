#include "runner/cli/identify_report.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "problems/pmsm/segments.hpp"
#include "runner/cli/formatted.hpp"

namespace mhb::cli {
namespace {

// A percentage, or "n/a" (same width) where it has no value.
std::string percent_text(double value, const char* f) {
    return std::isfinite(value) ? formatted(f, value) : std::string("      n/a  ");
}

} // namespace

void print_data_summary(std::ostream& out, const pmsm::PmsmSources& data) {
    for (std::size_t i = 0; i < data.datasets.size(); ++i) {
        const pmsm::Dataset& d = data.datasets[i];
        const auto [off, on] = d.state_counts();
        out << (i == 0 ? "data:    " : "         ") << data.names[i] << ": " << d.size() << " samples ("
            << off << " at id = 0, " << on << " injected)";
        try {
            const double Ts = pmsm::sampling_period(d, data.names[i]);
            const auto stretches = pmsm::contiguous_segments(d, Ts).size();
            out << ", Ts = " << formatted("%.6g", Ts) << " s, " << stretches
                << (stretches == 1 ? " stretch" : " stretches");
        } catch (const std::invalid_argument&) {
            out << ", no time step";
        }
        out << '\n';
    }
}

// One line per parameter: estimate, standard error, spread over seeds and error when known.
void print_estimates(std::ostream& out, const IdentifyReport& r) {
    const pmsm::LinearModel& model = r.id.model;
    const pmsm::LinearFit& fit = r.fit;
    const Eigen::VectorXd& estimate = r.estimate;
    const char* units[] = {"[ohm]", "[H]  ", "[H]  ", "[Wb] ", "[V]  "};
    out << "parameter   estimate        std. error      (% of est.)";
    if (r.id.output)
        out << "  spread over seeds";
    if (r.truth)
        out << "   true value      error";
    out << '\n';
    for (Eigen::Index j = 0; j < model.parameters(); ++j) {
        char buf[240];
        const double relative = 100.0 * fit.standard_error[j] / std::fabs(estimate[j]);
        // Never a nan or an inf as a number: "n/a" where the data give none.
        const bool determined = fit.determined[static_cast<std::size_t>(j)];
        std::snprintf(buf, sizeof buf, "%-3s %s   %-14s  %-14s  ",
                      model.parameter_names[static_cast<std::size_t>(j)].c_str(), units[j],
                      determined ? formatted("%.8g", estimate[j]).c_str() : "n/a",
                      std::isfinite(fit.standard_error[j]) ? formatted("%.4g", fit.standard_error[j]).c_str()
                                                           : "n/a");
        out << buf << percent_text(relative, "%9.3g %%");
        if (r.id.output) {
            std::snprintf(buf, sizeof buf, "  %-17.4g", r.id.output->spread[j]);
            out << buf;
        }
        if (r.truth) {
            const Eigen::VectorXd& truth = *r.truth;
            std::snprintf(buf, sizeof buf, "    %-14.8g  ", truth[j]);
            out << buf
                << percent_text(determined ? 100.0 * (estimate[j] - truth[j]) / truth[j] : NAN, "%+9.3g %%");
        }
        out << '\n';
    }
    out << '\n';
}

// The fit's value, residuals, condition and the Rs-psi correlation.
void print_fit(std::ostream& out, const IdentifyReport& r) {
    const pmsm::LinearFit& fit = r.fit;
    const double volts_per_unit = r.id.volts_per_unit;
    if (r.kind == pmsm::ModelKind::steady)
        out << formatted("f* (eq. 11 at the estimate) = %.10g\n", fit.f);
    else if (r.kind == pmsm::ModelKind::dynamic)
        out << formatted("f* (sum of 0.25 (r_d^2 + r_q^2) at the estimate) = %.10g\n", fit.f);
    else
        out << formatted(
            "f (sum of squared current errors at the estimate) = %.10g A^2; %.0f of %.0f seeds reached it "
            "(to 1e-6 relative)\n",
            r.id.output->best_f, r.id.output->seeds_at_best, static_cast<double>(r.id.output->seed_f.size()));
    for (const auto& [axis, stats] : {std::pair{"d", &fit.residual_d}, std::pair{"q", &fit.residual_q}})
        out << "residuals, " << axis << " axis: RMS " << formatted("%.4g ", stats->rms * volts_per_unit)
            << r.unit << formatted(", max %.4g ", stats->max_abs * volts_per_unit) << r.unit
            << ", lag-1 autocorrelation "
            << (std::isfinite(stats->lag1) ? formatted("%.3f", stats->lag1) : std::string("n/a")) << '\n';
    const Eigen::Index k = r.id.model.parameters();
    out << formatted("%.0f equations, %.0f parameters; condition number ",
                     static_cast<double>(r.id.model.equations()), static_cast<double>(k))
        << (std::isfinite(fit.condition_number) ? formatted("%.4g", fit.condition_number)
                                                : std::string("infinite"))
        << " (columns scaled to unit norm)\n";
    if (fit.covariance.allFinite() && k >= 4) {
        const double correlation =
            fit.covariance(0, 3) / std::sqrt(fit.covariance(0, 0) * fit.covariance(3, 3));
        if (std::isfinite(correlation))
            out << formatted("correlation of the Rs and psi estimates: %.3f\n", correlation);
    }
}

// The verdict on each parameter, and what to change in the experiment when it is not determined.
void print_verdicts(std::ostream& out, const IdentifyReport& r, const pmsm::Identifiability& judged) {
    out << "\nWhat the data determine:\n";
    const pmsm::LinearFit& fit = r.fit;
    const double residual_rms =
        std::sqrt((fit.residual_d.rms * fit.residual_d.rms + fit.residual_q.rms * fit.residual_q.rms) / 2.0);
    for (const pmsm::ParameterJudgement& p : judged.parameters) {
        out << "  " << p.name << ": " << pmsm::to_string(p.verdict) << " (" << p.reason << ")";
        if (std::isfinite(p.signal_rms) && residual_rms > 0)
            out << formatted("; its term is %.3g ", p.signal_rms * r.id.volts_per_unit) << r.unit
                << formatted(" RMS in the equations, %.3g times the residual RMS",
                             p.signal_rms / residual_rms);
        out << '\n';
        if (!p.advice.empty())
            out << "    to determine it: " << p.advice << '\n';
    }
    for (const std::string& note : judged.notes)
        out << "  note: " << note << '\n';
}

// What the standard errors (and the spread) do not say, and the problem's own warnings.
void print_caveats(std::ostream& out, const IdentifyReport& r, const Problem* problem,
                   const std::string& problem_spec) {
    const bool output = r.id.output.has_value();
    out << "\nStandard errors come from the residual variance and the fit's covariance"
        << (output ? " linearised at the estimate" : "")
        << ": how far noise alone\n"
           "moves the estimate (one sigma), assuming independent residuals. They do not cover systematic "
           "errors\n"
           "(inverter dead time and delay, a voltage offset, a model that misses part of the data), which "
           "show\n"
           "as correlated residuals above.\n";
    if (output)
        out << "The spread over seeds measures how reliably the optimiser finds the estimate, not the data's "
               "noise.\n";
    if (problem)
        for (const std::string& warning : problem->warnings())
            out << "note: as a problem of mhbench run (" << problem_spec << "): " << warning << '\n';
    const pmsm::LinearModel& model = r.id.model;
    for (Eigen::Index j = 0; j < model.parameters(); ++j)
        if (r.estimate[j] <= 0 && j < 4 && r.fit.determined[static_cast<std::size_t>(j)])
            out << "warning: " << model.parameter_names[static_cast<std::size_t>(j)]
                << " came out non-positive: the data do not support the model\n";
}

} // namespace mhb::cli
