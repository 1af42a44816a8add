// `mhbench identify`: identification of Rs, Ld, Lq and psi (and optionally the inverter's
// dead-time voltage) of a PMSM from a user's logged dq data, reported the way a motor engineer
// can use it: each estimate with its standard error and a plain verdict (determined / poorly
// determined / not identifiable from this data) saying what to change in the experiment, the
// residuals (RMS, maximum, lag-1 autocorrelation, which flags model error), the condition of the
// problem and, when the file carries the true values, the errors.
//
// With --flux-map FILE it identifies a machine's magnetic saturation from a measured flux map
// instead (identify_flux_map.hpp).
//
// Models: steady (eq. 11 of Li, Wang and Ji 2017) and dynamic (discrete dq voltage equations
// with di/dt) are linear in the parameters and solved exactly; output (output error) is not, so
// an optimiser is run from several seeds and their spread is reported besides the linearised
// standard errors.
#include <algorithm>
#include <boost/program_options.hpp>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/core/text_excerpt.hpp"
#include "problems/pmsm/dynamic_model.hpp"
#include "problems/pmsm/identifiability.hpp"
#include "problems/pmsm/pmsm_sources.hpp"
#include "problems/pmsm/steady_state_data.hpp"
#include "problems/problem_registry.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/identify_flux_map.hpp"
#include "runner/cli/identify_report.hpp"
#include "runner/cli/parse_command_line.hpp"
#include "runner/single_problem/output_error_search.hpp"

namespace mhb::cli {

namespace po = boost::program_options;

namespace {

pmsm::FitnessWeights parse_weights(const std::string& text) {
    std::vector<double> w;
    std::stringstream in(text);
    std::string cell;
    while (std::getline(in, cell, ',')) {
        double v = 0;
        if (!parse_real(cell, v) || v < 0)
            throw std::invalid_argument("--weights " + quoted_excerpt(text) + ": " + quoted_excerpt(cell) +
                                        " is not a number >= 0");
        w.push_back(v);
    }
    if (w.size() != 4)
        throw std::invalid_argument("--weights " + quoted_excerpt(text) + " needs four numbers w1,w2,w3,w4");
    // Each weight scales one equation's residuals: with all four zero every residual vanishes and
    // any parameters fit, so the table would be n/a throughout.
    if (std::all_of(w.begin(), w.end(), [](double v) { return v == 0.0; }))
        throw std::invalid_argument(
            "--weights " + quoted_excerpt(text) +
            ": all four are zero, which leaves nothing to fit; give at least one > 0");
    return {w[0], w[1], w[2], w[3]};
}

double positive_option(const std::string& text, const char* name) {
    double v = 0;
    if (!parse_real(text, v) || !(v > 0))
        throw std::invalid_argument(std::string("--") + name + " = " + value_excerpt(text) +
                                    " is not a number > 0");
    return v;
}

// The steady model as a linear model. With settled samples of both states in every dataset
// these are eq. 11's paired rows, exactly the `pmsm` problem's; otherwise (no injection, say)
// every settled row with weight 0.25, so that the verdict can say what the data lack instead of
// refusing them.
pmsm::LinearModel steady_model(const pmsm::PmsmSources& data, const pmsm::FitnessWeights& weights,
                               double settle, double& volts_per_unit) {
    pmsm::LinearModel model;
    model.parameter_names = {"Rs", "Ld", "Lq", "psi"};
    model.run_starts.clear();
    pmsm::SteadyStateData samples;
    std::vector<Eigen::Index> block_sizes;
    try {
        samples = pmsm::pair_samples(data.datasets, data.names, weights, settle);
        for (std::size_t i = 0; i < data.datasets.size(); ++i) {
            const Eigen::Index n = pmsm::pair_samples(data.datasets[i], weights, settle).pairs;
            block_sizes.insert(block_sizes.end(), {n, n});
        }
    } catch (const std::invalid_argument&) {
        // One state has no settled sample: every row as it is, weight 0.25 (eq. 2 stacked).
        Eigen::Index rows = 0;
        for (const pmsm::Dataset& d : data.datasets)
            rows += static_cast<Eigen::Index>(d.size());
        model.A = Eigen::MatrixXd::Zero(2 * rows, 4);
        model.b.resize(2 * rows);
        Eigen::Index r = 0;
        for (const pmsm::Dataset& d : data.datasets) {
            model.run_starts.push_back(r);
            for (std::size_t k = 0; k < d.size(); ++k, ++r) {
                model.A.row(r) << 0.5 * d.id[k], 0.0, -0.5 * d.omega[k] * d.iq[k], 0.0;
                model.b[r] = 0.5 * d.ud[k];
                model.A.row(rows + r) << 0.5 * d.iq[k], 0.5 * d.omega[k] * d.id[k], 0.0, 0.5 * d.omega[k];
                model.b[rows + r] = 0.5 * d.uq[k];
            }
        }
        model.d_rows = rows;
        volts_per_unit = 2.0;
        return model;
    }
    const pmsm::WeightedSystem system = pmsm::weighted_system(samples);
    model.A = system.A;
    model.b = system.b;
    model.d_rows = system.A.rows() / 2;
    Eigen::Index offset = 0;
    for (const Eigen::Index n : block_sizes) {
        model.run_starts.push_back(offset);
        offset += n;
    }
    const bool equal = weights.w1 == weights.w2 && weights.w2 == weights.w3 && weights.w3 == weights.w4;
    volts_per_unit = equal && weights.w1 > 0 ? 1.0 / std::sqrt(weights.w1) : 1.0;
    return model;
}

struct Options {
    std::string data;
    std::string model = "steady";
    std::string weights = "0.25,0.25,0.25,0.25";
    std::string threshold = "1";
    std::string settle = format_real(pmsm::default_settle_time);
    bool fit_vdt = false;
    std::string smooth = "0";
    std::string substeps = "2";
    OutputIdentificationOptions output;
    std::string seeds = "8", evaluations = "20000", threads = "0";
    std::string flux_map, bounds, starts = "100", seed = "1", out;
};

po::options_description make_identify_options(Options& o) {
    po::options_description options(
        "mhbench identify: estimate Rs, Ld, Lq and psi of a PMSM (and optionally the inverter's dead-time\n"
        "voltage) from logged dq data, with standard errors, a verdict per parameter saying whether the "
        "data\n"
        "determine it and what to change if not, and a residual report.\n"
        "Models: steady  eq. 11 of Li, Wang and Ji (2017) on the settled ends of the injection plateaus\n"
        "                (exact least squares);\n"
        "        dynamic the discrete dq voltage equations with di/dt on transient data (exact least "
        "squares);\n"
        "        output  output error: the currents simulated from the measured voltages and speed, fitted "
        "by\n"
        "                an optimiser from several seeds (their spread is reported).\n"
        "The dataset CSV: optional '# key=value' lines (Rs, Ld, Lq, psi give true values), then the header\n"
        "t,ud,uq,id,iq,omega[,injected] in s, V, V, A, A, electrical rad/s. Several files joined by '+' are\n"
        "fitted jointly (several operating conditions, one motor).\n\n"
        "With --flux-map FILE: the machine's magnetic saturation from a measured flux map (CSV columns\n"
        "i_d,i_q,psi_d,psi_q in A and V s; 'shipped' names the Baldor PM-SyRM map shipped with mhbench):\n"
        "--model pmsyrm (Lelli et al. 2024, 14 parameters; the default) or syrm (Hinkkanen et al. 2017, 9)\n"
        "fitted by a bounded Levenberg-Marquardt method from --starts random starts, with standard errors,\n"
        "verdicts, the current errors and a residual map; --out DIR adds CSVs and a figure of psi_d(i_d)\n"
        "and psi_q(i_q). The fit minimises the fluxmap problem of mhbench run (see mhbench list fluxmap).\n\n"
        "Usage: mhbench identify --data FILE[+FILE...] [--model steady|dynamic|output] [options]\n"
        "       mhbench identify --flux-map FILE|shipped [--model pmsyrm|syrm] [--out DIR] "
        "[options]\n\nOptions");
    // clang-format off
    options.add_options()
        ("help,h", "this text")
        ("data,d", po::value<std::string>(&o.data), "dataset CSV(s), joined by '+'; required")
        ("model,m", po::value<std::string>(&o.model)->default_value(o.model), "steady, dynamic or output")
        ("weights", po::value<std::string>(&o.weights)->default_value(o.weights),
         "steady: w1,w2,w3,w4 of eq. 11 (d and q residuals of the id = 0 state, then of the injected state)")
        ("id-threshold", po::value<std::string>(&o.threshold)->default_value(o.threshold),
         "without an 'injected' column, |id| above this (A) marks the injected state")
        ("settle", po::value<std::string>(&o.settle)->default_value(o.settle),
         "steady: samples less than this (s) after a switch of the injection state are not used")
        ("fit-vdt", po::bool_switch(&o.fit_vdt),
         "dynamic, output: also fit the inverter's dead-time voltage Vdt (V), which otherwise biases Rs")
        ("smooth", po::value<std::string>(&o.smooth)->default_value(o.smooth),
         "dynamic: centred moving average of 2K + 1 samples on every signal before di/dt (noisy currents)")
        ("substeps", po::value<std::string>(&o.substeps)->default_value(o.substeps),
         "output: RK4 steps per sampling period")
        ("algorithm", po::value<std::string>(&o.output.algorithm)->default_value(o.output.algorithm),
         "output: the optimiser (a spec, as in mhbench run); cmaes restarts with growing populations (IPOP)")
        ("seeds", po::value<std::string>(&o.seeds)->default_value(o.seeds), "output: independent runs")
        ("evaluations", po::value<std::string>(&o.evaluations)->default_value(o.evaluations),
         "output: evaluations per run")
        ("threads", po::value<std::string>(&o.threads)->default_value(o.threads),
         "output, flux map: threads (0: all cores)")
        ("flux-map", po::value<std::string>(&o.flux_map), "a flux-map CSV, or 'shipped' (instead of --data)")
        ("starts", po::value<std::string>(&o.starts)->default_value(o.starts),
         "flux map: Levenberg-Marquardt starts drawn uniformly from the box")
        ("seed", po::value<std::string>(&o.seed)->default_value(o.seed), "flux map: seed of the starts")
        ("bounds", po::value<std::string>(&o.bounds),
         "flux map: search bounds as in the fluxmap problem, e.g. 'a_d0=0:2000,S=1:8'")
        ("out", po::value<std::string>(&o.out),
         "flux map: a directory for estimates.csv, points.csv, curves.csv and the figure flux-map.pdf");
    // clang-format on
    return options;
}

// The options as values, checked; throws std::invalid_argument naming the first that is wrong.
struct Settings {
    pmsm::ModelKind kind = pmsm::ModelKind::steady;
    pmsm::DatasetReadOptions read_options;
    pmsm::FitnessWeights weights;
    double settle = 0;
    int smoothing = 0;
    int substeps = 2;
};

Settings check_settings(Options& o, const po::variables_map& vm) {
    if (o.data.empty())
        throw std::invalid_argument("--data FILE is required (see mhbench identify --help)");
    if (o.model != "steady" && o.model != "dynamic" && o.model != "output")
        throw std::invalid_argument("--model = " + value_excerpt(o.model) +
                                    " is not one of steady, dynamic, output");
    Settings s;
    s.kind = o.model == "steady"    ? pmsm::ModelKind::steady
             : o.model == "dynamic" ? pmsm::ModelKind::dynamic
                                    : pmsm::ModelKind::output;
    s.read_options.injection_threshold = positive_option(o.threshold, "id-threshold");
    s.read_options.require_both_states = false;
    s.weights = parse_weights(o.weights);
    if (!parse_real(o.settle, s.settle) || s.settle < 0)
        throw std::invalid_argument("--settle = " + value_excerpt(o.settle) + " is not a number >= 0");
    s.smoothing = static_cast<int>(integer_argument(o.smooth, "smooth", 0, 50));
    s.substeps = static_cast<int>(integer_argument(o.substeps, "substeps", 1, 1000));
    o.output.seeds = static_cast<int>(integer_argument(o.seeds, "seeds", 1, 10000));
    o.output.evaluations = integer_argument(o.evaluations, "evaluations", 1, 1000000000000LL);
    o.output.threads = static_cast<int>(integer_argument(o.threads, "threads", 0, 4096));
    if (s.kind == pmsm::ModelKind::steady && (o.fit_vdt || vm["smooth"].defaulted() == false))
        throw std::invalid_argument("--fit-vdt and --smooth apply to --model dynamic or output");
    return s;
}

// The options of a flux-map identification, checked.
FluxMapIdentifyOptions flux_map_settings(const Options& o, const po::variables_map& vm) {
    if (vm.count("data") != 0)
        throw std::invalid_argument(
            "--data (a PMSM dataset) and --flux-map are two identifications; give one");
    for (const char* pmsm_only :
         {"weights", "id-threshold", "settle", "smooth", "substeps", "algorithm", "seeds", "evaluations"})
        if (vm.count(pmsm_only) != 0 && !vm[pmsm_only].defaulted())
            throw std::invalid_argument(std::string("--") + pmsm_only +
                                        " applies to a PMSM dataset (--data), not to --flux-map");
    if (o.fit_vdt)
        throw std::invalid_argument("--fit-vdt applies to a PMSM dataset (--data), not to --flux-map");
    FluxMapIdentifyOptions f;
    f.map = o.flux_map;
    if (f.map.empty())
        throw std::invalid_argument("--flux-map needs a CSV file, or 'shipped' for the Baldor map");
    f.model = vm["model"].defaulted() ? "pmsyrm" : o.model;
    if (f.model != "pmsyrm" && f.model != "syrm")
        throw std::invalid_argument("--model = " + value_excerpt(f.model) +
                                    " is not a flux-map model; with --flux-map give pmsyrm or syrm");
    f.bounds = o.bounds;
    f.starts = static_cast<int>(integer_argument(o.starts, "starts", 1, 100000));
    f.seed = static_cast<std::uint64_t>(integer_argument(o.seed, "seed", 0, 9007199254740992LL));
    f.threads = static_cast<int>(integer_argument(o.threads, "threads", 0, 4096));
    f.out = o.out;
    return f;
}

// The same data as a `pmsm` problem of `mhbench run`: its search box and its warnings.
std::string problem_spec_of(const Options& o, const Settings& s) {
    std::string spec = "pmsm:model=" + o.model + ",data=" + o.data + ",id_threshold=" + o.threshold;
    if (s.kind == pmsm::ModelKind::steady) {
        spec += ",settle=" + o.settle;
        const char* keys[] = {"w1", "w2", "w3", "w4"};
        const double values[] = {s.weights.w1, s.weights.w2, s.weights.w3, s.weights.w4};
        for (int j = 0; j < 4; ++j)
            spec += std::string(",") + keys[j] + "=" + format_real(values[j]);
    } else {
        spec += ",fit_vdt=" + std::string(o.fit_vdt ? "on" : "off");
        spec += s.kind == pmsm::ModelKind::dynamic ? ",smooth=" + std::to_string(s.smoothing)
                                                   : ",substeps=" + std::to_string(s.substeps);
    }
    return spec;
}

// Made once: the output model optimises it, and every model reports its warnings. Data that the
// linear models cannot determine make no problem (none is returned); identify still judges them.
std::unique_ptr<Problem> make_problem(const std::string& spec, pmsm::ModelKind kind) {
    try {
        return builtin_problems().create(Spec::parse(spec));
    } catch (const std::invalid_argument& e) {
        if (kind == pmsm::ModelKind::output) // failed work (exit 1), as for the other models below
            throw std::runtime_error(e.what());
    } catch (const std::exception&) {
        if (kind == pmsm::ModelKind::output)
            throw;
    }
    return nullptr;
}

Identification identify(const Options& o, const Settings& s, const pmsm::PmsmSources& data,
                        const Problem* problem) {
    Identification id;
    try {
        if (s.kind == pmsm::ModelKind::steady) {
            id.model = steady_model(data, s.weights, s.settle, id.volts_per_unit);
            id.title = "steady-state model (eq. 11 of Li, Wang and Ji 2017), exact least squares";
        } else if (s.kind == pmsm::ModelKind::dynamic) {
            pmsm::DynamicModelOptions dynamic;
            dynamic.fit_dead_time = o.fit_vdt;
            dynamic.smoothing = s.smoothing;
            id.model = pmsm::dynamic_model(data.datasets, data.names, dynamic);
            id.title = "dynamic model (discrete dq voltage equations with di/dt), exact least squares";
        } else {
            const auto& output_problem = dynamic_cast<const pmsm::OutputErrorProblem&>(*problem);
            id.output = identify_output_error(output_problem, o.output);
            id.model = id.output->linearised;
            id.volts_per_unit = 1.0;
            id.title = "output-error model (simulated against measured currents), " + o.output.algorithm +
                       " from " + std::to_string(o.output.seeds) + " seeds of " +
                       std::to_string(o.output.evaluations) + " evaluations";
        }
    } catch (const std::invalid_argument& e) {
        // Data that do not make the model are failed work (exit 1), not a bad command line.
        throw std::runtime_error(e.what());
    }
    return id;
}

// True values from the metadata, for the model's coordinates.
std::optional<Eigen::VectorXd> true_values(const pmsm::PmsmSources& data, Eigen::Index k) {
    std::optional<Eigen::VectorXd> truth;
    if (const auto nominal = data.nominal_parameters()) {
        truth = Eigen::VectorXd(k);
        truth->head<4>() = *nominal;
        if (k == 5)
            (*truth)[4] = pmsm::dead_time_voltage(data.datasets.front());
    }
    return truth;
}

} // namespace

int run_identify_command(const std::vector<std::string>& args) {
    Options o;
    const po::options_description options = make_identify_options(o);
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { std::cout << options << '\n'; }))
        return exit_ok;
    if (vm.count("flux-map") != 0)
        return identify_flux_map(flux_map_settings(o, vm));
    for (const char* flux_only : {"starts", "seed", "bounds", "out"})
        if (!vm[flux_only].defaulted() && vm.count(flux_only) != 0)
            throw std::invalid_argument(std::string("--") + flux_only + " applies to --flux-map only");
    const Settings settings = check_settings(o, vm);

    const pmsm::PmsmSources data = pmsm::read_sources(o.data, settings.read_options);
    const std::string problem_spec = problem_spec_of(o, settings);
    const std::unique_ptr<Problem> problem = make_problem(problem_spec, settings.kind);
    const Identification id = identify(o, settings, data, problem.get());
    const pmsm::LinearFit fit = pmsm::fit_linear_model(id.model);
    const pmsm::Identifiability judged = pmsm::judge_identifiability(id.model, fit, settings.kind);
    const Eigen::VectorXd estimate = id.output ? id.output->best_x : fit.theta;
    const std::optional<Eigen::VectorXd> truth = true_values(data, id.model.parameters());
    const char* unit =
        settings.kind == pmsm::ModelKind::output ? "A" : (id.volts_per_unit == 1.0 ? "(weighted)" : "V");
    const IdentifyReport report{id, fit, estimate, truth, settings.kind, unit};

    std::ostream& out = std::cout;
    out << "PMSM identification: " << id.title << '\n';
    print_data_summary(out, data);
    out << (id.volts_per_unit == 1.0 && settings.kind != pmsm::ModelKind::output
                ? "weights: " + o.weights + "\n"
                : "")
        << '\n';
    print_estimates(out, report);
    print_fit(out, report);
    print_verdicts(out, report, judged);
    print_caveats(out, report, problem.get(), problem_spec);
    return exit_ok;
}

} // namespace mhb::cli
