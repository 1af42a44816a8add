#include "problems/pmsm/identifiability.hpp"

#include <cmath>
#include <cstdio>
#include <utility>

namespace mhb::pmsm {
namespace {

std::string number(const char* format, double value) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, value);
    return buf;
}

// What carries each parameter in each model, and how to make it larger.
std::string advice_for(const std::string& name, ModelKind kind) {
    const bool steady = kind == ModelKind::steady;
    if (name == "Rs")
        return "its signal is Rs i in the voltages: inject a larger d-axis current or run at a larger load, "
               "take "
               "more samples, and fit the inverter's dead-time voltage (fit_vdt) if it has one, since both "
               "act like a resistance";
    if (name == "Ld")
        return steady
                   ? "its signal is omega Ld id in uq: inject a larger d-axis current, or run faster"
                   : "its signals are Ld did/dt in ud and omega Ld id in uq: include d-current steps in the "
                     "window, or inject a larger d-axis current";
    if (name == "Lq")
        return steady
                   ? "its signal is omega Lq iq in ud: run at a larger load or speed"
                   : "its signals are Lq diq/dt in uq and omega Lq iq in ud: include q-current steps (a load "
                     "or speed change), or run at a larger load";
    if (name == "psi")
        return "its signal is psi omega in uq, which at one constant speed looks like Rs iq: record several "
               "speeds (a wider speed range, or conditions joined with '+')";
    if (name == "Vdt")
        return "its signal is Vdt i/|i|, which at a fixed current angle looks like a resistance: vary the "
               "current angle (inject d current of both signs, or change the load)";
    return {};
}

constexpr double lag1_limit = 0.5; // |lag-1 autocorrelation| above this: the residuals are not white noise

} // namespace

const char* to_string(ModelKind kind) {
    switch (kind) {
    case ModelKind::steady:
        return "steady";
    case ModelKind::dynamic:
        return "dynamic";
    case ModelKind::output:
        return "output";
    }
    return "?";
}

const char* to_string(Verdict verdict) {
    switch (verdict) {
    case Verdict::determined:
        return "determined";
    case Verdict::poorly_determined:
        return "poorly determined";
    case Verdict::not_identifiable:
        return "not identifiable from this data";
    }
    return "?";
}

Identifiability judge_identifiability(const LinearModel& model, const LinearFit& fit, ModelKind kind) {
    Identifiability out;
    out.condition_number = fit.condition_number;
    const Eigen::Index k = model.parameters();
    const Eigen::Index m = model.equations();

    const Eigen::VectorXd& weakest = fit.weakest_direction;
    for (Eigen::Index j = 0; j < k; ++j) {
        ParameterJudgement p;
        p.name = model.parameter_names[static_cast<std::size_t>(j)];
        const double estimate = fit.theta[j];
        p.relative_error = fit.standard_error[j] / std::fabs(estimate);
        p.weak_direction = weakest[j];
        p.signal_rms = std::sqrt((model.A.col(j) * estimate).squaredNorm() / static_cast<double>(m));
        const bool collinear = weakest[j] > 0.1;
        const bool determined = fit.determined[static_cast<std::size_t>(j)];
        if (!determined) {
            p.verdict = Verdict::not_identifiable;
            p.reason = "the data leave it undetermined (its column is a combination of the others', or zero)";
        } else if (!std::isfinite(p.relative_error) && std::isnan(fit.standard_error[j])) {
            p.verdict = Verdict::not_identifiable;
            p.reason = "no residual is left to estimate its error from (too few equations)";
        } else if (!(p.relative_error <= 0.5)) {
            p.verdict = Verdict::not_identifiable;
            p.reason =
                "its standard error is " + number("%.3g", 100 * p.relative_error) + " % of the estimate";
        } else if (fit.condition_number > 1e8 && collinear) {
            p.verdict = Verdict::not_identifiable;
            p.reason = "it is nearly collinear with other parameters (condition number " +
                       number("%.3g", fit.condition_number) + ")";
        } else if (p.relative_error > 0.05) {
            p.verdict = Verdict::poorly_determined;
            p.reason =
                "its standard error is " + number("%.3g", 100 * p.relative_error) + " % of the estimate";
        } else if (fit.condition_number > 1e5 && collinear) {
            p.verdict = Verdict::poorly_determined;
            p.reason = "it shares the weakest direction of an ill-conditioned fit (condition number " +
                       number("%.3g", fit.condition_number) + ")";
        } else {
            p.reason = "standard error " + number("%.3g", 100 * p.relative_error) + " % of the estimate";
        }
        if (p.verdict != Verdict::determined)
            p.advice = advice_for(p.name, kind);
        out.parameters.push_back(std::move(p));
    }

    if (m < 25 * k)
        out.notes.push_back(std::to_string(m) + " equations for " + std::to_string(k) +
                            " parameters: a longer window (more samples) narrows every error");
    for (const auto& [axis, stats] : {std::pair{"d", &fit.residual_d}, std::pair{"q", &fit.residual_q}})
        if (std::isfinite(stats->lag1) && std::fabs(stats->lag1) > lag1_limit)
            out.notes.push_back(
                std::string("the ") + axis +
                "-axis residuals are correlated from one sample to the "
                "next (lag-1 autocorrelation " +
                number("%.2f", stats->lag1) +
                "): the model misses part of the data (a transient in a steady model, dead time, "
                "delay, filtering), so the standard errors are too small");
    return out;
}

} // namespace mhb::pmsm
