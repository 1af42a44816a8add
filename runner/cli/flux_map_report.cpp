#include "runner/cli/flux_map_report.hpp"

#include <cmath>
#include <cstdio>

#include "runner/cli/formatted.hpp"

namespace mhb::cli {
namespace {

std::string range(const Eigen::ArrayXd& values, const char* unit) {
    return formatted("%.4g to %.4g ", values.minCoeff(), values.maxCoeff()) + unit;
}

void print_header(std::ostream& out, const FluxMapReport& r) {
    const bool pm = r.map.model() == fluxmap::Model::pmsyrm;
    const fluxmap::FluxMap& m = r.map.map();
    out << "Flux-map identification: "
        << (pm ? "PM-SyRM current map (Lelli et al. 2024" : "SyRM current map (Hinkkanen et al. 2017") << ", "
        << fluxmap::parameter_count(r.map.model()) << " parameters), bounded Levenberg-Marquardt from "
        << r.fit.start_f.size() << " starts\n";
    out << "map:  " << r.map_name << ": " << m.size() << " points, i_d " << range(m.i_d, "A") << ", i_q "
        << range(m.i_q, "A") << ", psi_d " << range(m.psi_d, "V s") << ", psi_q " << range(m.psi_q, "V s")
        << '\n';
    out << formatted("fit:  f = %.12g A^2 (the sum of squared current errors); ", r.fit.f) << r.reached
        << " of " << r.fit.start_f.size() << " starts reached it (within 1e-6 relative)\n";
    if (r.known)
        out << formatted("      the shipped best-known f* is %.17g A^2; this fit is %.2g relative to it\n",
                         r.known->f, (r.fit.f - r.known->f) / r.known->f);
    out << '\n';
}

void print_estimates(std::ostream& out, const FluxMapReport& r) {
    out << "parameter  estimate          std. error    (% of est.)  spread over starts  verdict\n";
    for (const fluxmap::ParameterAssessment& p : r.assessment.parameters) {
        char buf[320];
        std::snprintf(
            buf, sizeof buf, "%-9s  %-16.10g  %-12s  %-11s  %-18.3g  %s\n", p.name.c_str(), p.estimate,
            std::isfinite(p.standard_error) ? formatted("%.4g", p.standard_error).c_str() : "n/a",
            std::isfinite(p.relative_error) ? formatted("%.3g %%", 100 * p.relative_error).c_str() : "n/a",
            p.spread, fluxmap::to_string(p.verdict));
        out << buf;
    }
    out << '\n';
}

void print_errors(std::ostream& out, const FluxMapReport& r) {
    const fluxmap::CurrentErrors& e = r.assessment.errors;
    const fluxmap::FluxMap& m = r.map.map();
    out << formatted("current error: RMS %.4g A (d axis %.4g A, q axis %.4g A); ", e.rms, e.rms_d, e.rms_q)
        << formatted("worst %.4g A at i_d = %.4g A, ", e.worst, m.i_d[e.worst_point])
        << formatted("i_q = %.4g A\n", m.i_q[e.worst_point]);
    out << formatted("residual sigma %.4g A (%.0f residuals, ", r.assessment.residual_sigma,
                     2.0 * static_cast<double>(m.size()))
        << r.assessment.free_parameters << " free parameters); condition number "
        << (std::isfinite(r.assessment.condition_number) ? formatted("%.3g", r.assessment.condition_number)
                                                         : "infinite")
        << " (columns scaled to unit norm)\n";
    out << formatted("neighbouring points' residuals correlate %.2f", e.neighbour_correlation)
        << (std::fabs(e.neighbour_correlation) > 0.5
                ? ": the misfit is smooth, the model's own, not measurement noise\n"
                : ": the misfit looks like noise\n");
}

void print_residual_map(std::ostream& out, const FluxMapReport& r) {
    const fluxmap::ResidualMap& rm = r.residual_map;
    out << "\nResidual map: RMS current error (A) of the points in each region (rows i_q, columns i_d, "
           "bin centres in A)\n";
    out << "  i_q \\ i_d";
    for (std::size_t c = 0; c + 1 < rm.d_edges.size(); ++c)
        out << formatted("%8.3g", (rm.d_edges[c] + rm.d_edges[c + 1]) / 2);
    out << '\n';
    for (auto row = static_cast<Eigen::Index>(rm.q_edges.size()) - 2; row >= 0; --row) {
        const auto q = static_cast<std::size_t>(row);
        out << formatted("  %8.3g ", (rm.q_edges[q] + rm.q_edges[q + 1]) / 2);
        for (Eigen::Index c = 0; c < rm.rms.cols(); ++c)
            out << (std::isfinite(rm.rms(row, c)) ? formatted("%8.3f", rm.rms(row, c))
                                                  : std::string("       ."));
        out << '\n';
    }
}

void print_verdicts(std::ostream& out, const FluxMapReport& r) {
    out << "\nWhat the map determines:\n";
    for (const fluxmap::ParameterAssessment& p : r.assessment.parameters)
        out << "  " << p.name << ": " << fluxmap::to_string(p.verdict) << " (" << p.reason << ")\n";
    out << "\nStandard errors come from the residual variance and the fit's covariance linearised at the "
           "estimate:\nhow far independent errors of this size would move the estimate (one sigma). A "
           "smooth misfit\n(correlated neighbours above) is the model's, and then they measure how well the "
           "map pins the\nparameters of this model, not how close they are to the machine's physics. The "
           "spread over starts\nsays how reliably the fit finds this optimum, not the data's noise.\n";
    for (const std::string& warning : r.warnings)
        out << "note: " << warning << '\n';
}

} // namespace

void print_flux_map_report(std::ostream& out, const FluxMapReport& report) {
    print_header(out, report);
    print_estimates(out, report);
    print_errors(out, report);
    print_residual_map(out, report);
    print_verdicts(out, report);
}

} // namespace mhb::cli
