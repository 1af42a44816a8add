// The flux-map path of `mhbench identify` (identify_flux_map.hpp): the problem of `mhbench run`
// (its checks, box and bounds), the parallel multi-start fit, the assessment, the printed report
// and, with --out, the files and the figure.
#include "runner/cli/identify_flux_map.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "problems/core/spec.hpp"
#include "problems/core/text_excerpt.hpp"
#include "problems/fluxmap/fit_assessment.hpp"
#include "problems/fluxmap/flux_map.hpp"
#include "problems/fluxmap/residual_map.hpp"
#include "problems/problem_registry.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/flux_map_files.hpp"
#include "runner/cli/flux_map_report.hpp"
#include "runner/single_problem/flux_map_search.hpp"

namespace mhb::cli {
namespace {

constexpr double reached_relative = 1e-6; // a start within this of the best reached it
constexpr int residual_columns = 7;       // i_d bins of the residual map (a terminal's width)
constexpr int residual_rows = 9;          // i_q bins

// --bounds holds `name=lo:hi` items for the model's parameters only: the fluxmap family's other
// keys (data, synthetic, ...) would change the problem under the fit.
void check_bound_names(const FluxMapIdentifyOptions& o, fluxmap::Model model) {
    const std::vector<std::string> names = fluxmap::parameter_names(model);
    std::string known;
    for (const std::string& name : names)
        known += (known.empty() ? "" : " ") + name;
    std::size_t start = 0;
    while (start < o.bounds.size()) {
        const std::size_t comma = std::min(o.bounds.find(',', start), o.bounds.size());
        const std::string item = o.bounds.substr(start, comma - start);
        const std::string key = item.substr(0, item.find('='));
        if (std::find(names.begin(), names.end(), key) == names.end())
            throw std::invalid_argument("--bounds " + quoted_excerpt(o.bounds) + ": " + quoted_excerpt(key) +
                                        " is not a parameter of model=" + o.model + " (" + known + ")");
        start = comma + 1;
    }
}

std::string problem_spec_of(const FluxMapIdentifyOptions& o) {
    std::string spec = "fluxmap:model=" + o.model;
    if (o.map != shipped_map_word)
        spec += ",data=" + o.map;
    if (!o.bounds.empty())
        spec += "," + o.bounds;
    return spec;
}

} // namespace

int identify_flux_map(const FluxMapIdentifyOptions& o) {
    const fluxmap::Model model = o.model == "syrm" ? fluxmap::Model::syrm : fluxmap::Model::pmsyrm;
    check_bound_names(o, model);
    const std::string spec = problem_spec_of(o);
    // The problem checks the file, the model and the bounds as `mhbench run` does; a defect of the
    // file is failed work (exit 1), a wrong bound a wrong command line (exit 2).
    const std::unique_ptr<Problem> problem = builtin_problems().create(Spec::parse(spec));
    const bool shipped = o.map == shipped_map_word;
    const fluxmap::FluxMap data =
        shipped ? fluxmap::baldor_flux_map() : fluxmap::read_flux_map_csv(o.map, problem->dimension());
    const fluxmap::CurrentMap map(model, data);
    if (!o.out.empty())
        prepare_output_directory(o.out); // before the fit: an unwritable directory fails at once

    fluxmap::FitOptions fit_options;
    fit_options.starts = o.starts;
    fit_options.seed = o.seed;
    const FluxMapSearch search = search_flux_map(map, problem->bounds(), fit_options, o.threads);
    std::vector<Eigen::VectorXd> reached;
    for (std::size_t s = 0; s < search.start_theta.size(); ++s)
        if (search.best.start_f[s] <= search.best.f * (1 + reached_relative))
            reached.push_back(search.start_theta[s]);
    const fluxmap::FitAssessment assessment =
        fluxmap::assess_fit(map, problem->bounds(), search.best.theta, reached);
    Eigen::VectorXd residuals;
    map.residuals(search.best.theta, residuals);

    const FluxMapReport report{map,
                               problem->bounds(),
                               assessment,
                               search.best,
                               static_cast<int>(reached.size()),
                               shipped ? std::string(fluxmap::baldor_map_name) + " (shipped)" : o.map,
                               problem->known_optimum(),
                               fluxmap::residual_map(data, residuals, residual_columns, residual_rows),
                               problem->warnings()};
    print_flux_map_report(std::cout, report);
    if (!o.out.empty())
        write_flux_map_files(o.out, report, std::cout);
    else
        std::cout
            << "\nWith --out DIR: the estimates, every point's current error and the fitted curves as CSV, "
               "and a figure.\n";
    return exit_ok;
}

} // namespace mhb::cli
