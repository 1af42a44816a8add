// `mhbench identify`: the least-squares identification of Rs, Ld, Lq and psi from a user's
// steady-state dataset (eq. 11 of Li, Wang and Ji 2017, solved exactly), reported the way a motor
// engineer can use it: each estimate with its standard error, the fit's residuals, the condition
// of the problem and, when the file carries the true values, the errors.
#include <boost/program_options.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/parameters.hpp"
#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/least_squares.hpp"
#include "problems/pmsm/steady_state_data.hpp"
#include "problems/pmsm/steady_state_problem.hpp"
#include "problems/text_excerpt.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"

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
    return {w[0], w[1], w[2], w[3]};
}

std::string line(const char* format, double a, double b, double c) {
    char buf[200];
    std::snprintf(buf, sizeof buf, format, a, b, c);
    return buf;
}

// A percentage, or "n/a" (same width) where it has no value: an estimate or a true value of 0.
std::string percent_text(double value, const char* format) {
    if (!std::isfinite(value))
        return "      n/a  ";
    char buf[64];
    std::snprintf(buf, sizeof buf, format, value);
    return buf;
}

} // namespace

int run_identify_command(const std::vector<std::string>& args) {
    std::string data_path;
    std::string weights_text = "0.25,0.25,0.25,0.25";
    std::string threshold_text = "1";
    po::options_description options(
        "mhbench identify: estimate Rs, Ld, Lq and psi of a PMSM from steady-state dq data by exact\n"
        "least squares on the paper's fitness (Li, Wang and Ji 2017, eq. 11), with standard errors.\n"
        "The dataset CSV: optional '# key=value' lines (Rs, Ld, Lq, psi give true values), then the\n"
        "header t,ud,uq,id,iq,omega[,injected] in s, V, V, A, A, electrical rad/s; samples of the\n"
        "id = 0 state and of the injected state (the 'injected' column, or |id| above a threshold).\n\n"
        "Usage: mhbench identify --data FILE [options]\n\nOptions");
    // clang-format off
    options.add_options()
        ("help,h", "this text")
        ("data,d", po::value<std::string>(&data_path), "dataset CSV; required")
        ("weights", po::value<std::string>(&weights_text)->default_value(weights_text),
         "w1,w2,w3,w4 of eq. 11: d and q residuals of the id = 0 state, then of the injected state")
        ("id-threshold", po::value<std::string>(&threshold_text)->default_value(threshold_text),
         "without an 'injected' column, |id| above this (A) marks the injected state");
    // clang-format on
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { std::cout << options << '\n'; }))
        return exit_ok;
    if (data_path.empty())
        throw std::invalid_argument("--data FILE is required (see mhbench identify --help)");
    double threshold = 0;
    if (!parse_real(threshold_text, threshold) || !(threshold > 0))
        throw std::invalid_argument("--id-threshold = " + value_excerpt(threshold_text) +
                                    " is not a number > 0");
    const pmsm::FitnessWeights weights = parse_weights(weights_text);

    pmsm::DatasetReadOptions read_options;
    read_options.injection_threshold = threshold;
    const pmsm::Dataset data = pmsm::read_dataset_csv(data_path, read_options);
    const pmsm::SteadyStateData samples = pmsm::pair_samples(data, weights);
    // Data that do not determine the parameters are failed work (exit 1), not a bad command line.
    pmsm::LeastSquaresResult r;
    try {
        r = pmsm::solve_least_squares(samples);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(data_path + ": " + e.what());
    }
    // Never print inf or nan as an estimate or a standard error: say why there is none.
    if (!r.standard_error.allFinite()) {
        if (r.equations <= 4)
            throw std::runtime_error(data_path + ": " + std::to_string(r.equations) +
                                     " equations for 4 parameters leave no residual to estimate the "
                                     "standard errors from; give more samples in each state");
        throw std::runtime_error(data_path + ": the standard errors are not finite (condition number " +
                                 line("%.3g", r.condition_number, 0, 0) +
                                 "): the data do not determine the four parameters");
    }
    const auto truth = data.true_parameters();
    const auto [off, on] = data.state_counts();

    std::ostream& out = std::cout;
    out << "PMSM steady-state identification (least squares on eq. 11 of Li, Wang and Ji 2017)\n"
        << "data:    " << data_path << ": " << data.size() << " samples, " << off << " at id = 0 and " << on
        << " injected; " << samples.pairs << " pairs used\n"
        << "weights: " << format_real(weights.w1) << ' ' << format_real(weights.w2) << ' '
        << format_real(weights.w3) << ' ' << format_real(weights.w4) << "\n\n";
    const char* names[] = {"Rs  [ohm]", "Ld  [H]  ", "Lq  [H]  ", "psi [Wb] "};
    out << "parameter   estimate        std. error      (% of est.)";
    if (truth)
        out << "   true value      error";
    out << '\n';
    for (int j = 0; j < 4; ++j) {
        char buf[240];
        const double relative = 100.0 * r.standard_error[j] / std::fabs(r.theta[j]);
        std::snprintf(buf, sizeof buf, "%s   %-14.8g  %-14.4g  ", names[j], r.theta[j], r.standard_error[j]);
        out << buf << percent_text(relative, "%9.3g %%");
        if (truth) {
            std::snprintf(buf, sizeof buf, "     %-14.8g  ", (*truth)[j]);
            out << buf << percent_text(100.0 * (r.theta[j] - (*truth)[j]) / (*truth)[j], "%+9.3g %%");
        }
        out << '\n';
    }
    out << '\n'
        << line("f* (eq. 11 at the estimate) = %.10g;  residual RMS: d axis %.4g V, q axis %.4g V\n", r.f,
                r.residual_rms_d, r.residual_rms_q);
    const double correlation = r.covariance(0, 3) / std::sqrt(r.covariance(0, 0) * r.covariance(3, 3));
    out << line("%.0f equations, 4 parameters; condition number %.4g (columns scaled to unit norm); ",
                static_cast<double>(r.equations), r.condition_number, 0)
        << "correlation of Rs and psi "
        << (std::isfinite(correlation) ? line("%.3f", correlation, 0, 0) : std::string("n/a (an exact fit)"))
        << '\n';
    if (truth && std::isfinite(samples.fitness(*truth))) {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "f at the true values = %.10g (f - f* = %.4g: how far the data move the optimum)\n",
                      samples.fitness(*truth), samples.fitness(*truth) - r.f);
        out << buf;
    }
    out << "\nStandard errors are sigma^2 (A^T W A)^-1 from the residual: they measure how far noise alone "
           "can\n"
           "move the estimate (one sigma), assuming independent residuals. They do not cover systematic\n"
           "errors - inverter dead time and delay, a voltage offset - which bias Rs above all: its only\n"
           "signal is Rs id in ud (about 0.66 V at -2 A), and Rs and psi are strongly correlated.\n";
    for (int j = 0; j < 4; ++j)
        if (r.theta[j] <= 0)
            out << "warning: " << names[j] << " came out non-positive: the data do not support the model\n";
    if (!pmsm::paper_bounds().contains(r.theta))
        out << "note: the estimate lies outside the paper's search box (Rs 0-0.5, Ld and Lq 0-0.01, psi "
               "0-0.1); an\n"
               "optimiser confined to that box cannot reach it (pmsm: reports the box-constrained optimum)\n";
    if (r.standard_error[0] > 0.1 * std::fabs(r.theta[0]))
        out << "warning: Rs is determined to worse than 10 %; a larger injection or more samples help\n";
    return exit_ok;
}

} // namespace mhb::cli
