#include "runner/cli/flux_map_files.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "problems/fluxmap/fitted_curves.hpp"
#include "results/report/child_process.hpp"
#include "results/report/report.hpp"
#include "results/store/csv.hpp"
#include "runner/execution/companion_files.hpp"

namespace mhb::cli {
namespace fs = std::filesystem;
namespace {

constexpr int curve_levels_shown = 5;
constexpr int curve_samples = 121;

std::string estimates_csv(const FluxMapReport& r) {
    std::ostringstream s;
    s << "parameter,estimate,standard_error,relative_error,spread_over_starts,verdict,lower,upper\n";
    for (std::size_t j = 0; j < r.assessment.parameters.size(); ++j) {
        const fluxmap::ParameterAssessment& p = r.assessment.parameters[j];
        const auto i = static_cast<Eigen::Index>(j);
        s << p.name << ',' << csv_number(p.estimate) << ',' << csv_number(p.standard_error) << ','
          << csv_number(p.relative_error) << ',' << csv_number(p.spread) << ','
          << fluxmap::to_string(p.verdict) << ',' << csv_number(r.box.lower[i]) << ','
          << csv_number(r.box.upper[i]) << '\n';
    }
    return s.str();
}

std::string points_csv(const FluxMapReport& r) {
    Eigen::ArrayXd i_d, i_q;
    r.map.currents(r.fit.theta, i_d, i_q);
    const fluxmap::FluxMap& m = r.map.map();
    std::ostringstream s;
    s << "i_d,i_q,psi_d,psi_q,i_d_model,i_q_model,error_d,error_q\n";
    for (Eigen::Index k = 0; k < m.size(); ++k)
        s << csv_number(m.i_d[k]) << ',' << csv_number(m.i_q[k]) << ',' << csv_number(m.psi_d[k]) << ','
          << csv_number(m.psi_q[k]) << ',' << csv_number(i_d[k]) << ',' << csv_number(i_q[k]) << ','
          << csv_number(i_d[k] - m.i_d[k]) << ',' << csv_number(i_q[k] - m.i_q[k]) << '\n';
    return s.str();
}

std::string curves_csv(const FluxMapReport& r) {
    const fluxmap::FluxMap& m = r.map.map();
    const auto curves =
        fluxmap::fitted_curves(r.map, r.fit.theta, fluxmap::curve_levels(m.i_q, curve_levels_shown, true),
                               fluxmap::curve_levels(m.i_d, curve_levels_shown, false), curve_samples);
    std::ostringstream s;
    s << "curve,level,i_d,i_q,psi_d,psi_q\n";
    for (const fluxmap::FluxCurve& c : curves)
        for (Eigen::Index k = 0; k < c.i_d.size(); ++k)
            s << (c.d_axis ? "psi_d(i_d)" : "psi_q(i_q)") << ',' << csv_number(c.level) << ','
              << csv_number(c.i_d[k]) << ',' << csv_number(c.i_q[k]) << ',' << csv_number(c.psi_d[k]) << ','
              << csv_number(c.psi_q[k]) << '\n';
    return s.str();
}

void draw_figure(const fs::path& dir, const FluxMapReport& r, std::ostream& console) {
    const auto python = find_matplotlib_python(ReportOptions().python_candidates);
    if (!python) {
        console << "figure skipped: no Python with matplotlib found (apt install python3-matplotlib); the "
                   "curves are in curves.csv\n";
        return;
    }
    const std::string title = std::string(r.map.model() == fluxmap::Model::pmsyrm ? "PM-SyRM" : "SyRM") +
                              " fitted to " + fs::path(r.map_name).filename().string();
    const fs::path script = companion_file("scripts/plot_flux_map.py");
    if (!fs::exists(script)) {
        console << "figure skipped: the plotting script " << script.string()
                << " was not found (an incomplete installation); the curves are in curves.csv\n";
        return;
    }
    const ChildOutcome run = run_child_process(*python, {script.string(), dir.string(), title}, true);
    if (run.exited_with(0)) {
        console << "figure: " << (dir / "flux-map.pdf").string() << " (and .png)\n";
        return;
    }
    const std::string said = run.err.empty() ? run.out : run.err;
    const auto last = said.find_last_not_of('\n');
    const auto line_start = last == std::string::npos ? 0 : said.rfind('\n', last);
    console << "figure failed: "
            << (run.started ? said.substr(line_start == std::string::npos ? 0 : line_start + 1) : run.error)
            << '\n';
}

} // namespace

void prepare_output_directory(const std::string& dir) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw std::runtime_error("--out " + dir + ": is a file, not a directory");
    fs::create_directories(dir, ec);
    if (ec)
        throw std::runtime_error("--out " + dir + ": cannot create the directory: " + ec.message());
    const fs::path probe = fs::path(dir) / ".mhbench-write-check";
    if (!std::ofstream(probe))
        throw std::runtime_error("--out " + dir + ": cannot write in the directory (permission denied?)");
    fs::remove(probe, ec);
}

void write_flux_map_files(const std::string& dir, const FluxMapReport& report, std::ostream& console) {
    const fs::path out(dir);
    write_file_atomically(out / "estimates.csv", estimates_csv(report));
    write_file_atomically(out / "points.csv", points_csv(report));
    write_file_atomically(out / "curves.csv", curves_csv(report));
    console << "\nwritten: " << (out / "estimates.csv").string() << ", points.csv, curves.csv\n";
    draw_figure(out, report, console);
}

} // namespace mhb::cli
