#include "problems/pmsm/dynamic_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "problems/core/parameters.hpp"
#include "problems/pmsm/segments.hpp"

namespace mhb::pmsm {
namespace {

// sqrt of the weight 0.25 of every equation, folded into its row of A and b.
constexpr double row_factor = 0.5;

// The signals of one segment, smoothed when asked.
struct Signals {
    std::vector<double> ud, uq, id, iq, omega;
};

// Centred moving average over 2h + 1 samples with h = min(K, distance to the nearer end): the
// window shrinks symmetrically so that the filter stays centred (no phase shift) up to the ends.
std::vector<double> moving_average(const std::vector<double>& x, const Segment& seg, int half_width) {
    const auto n = static_cast<std::ptrdiff_t>(seg.size());
    const auto* in = x.data() + seg.begin;
    std::vector<double> out(seg.size());
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        const std::ptrdiff_t h = std::min<std::ptrdiff_t>({half_width, i, n - 1 - i});
        double sum = 0.0;
        for (std::ptrdiff_t j = i - h; j <= i + h; ++j)
            sum += in[j];
        out[static_cast<std::size_t>(i)] = sum / static_cast<double>(2 * h + 1);
    }
    return out;
}

Signals segment_signals(const Dataset& data, const Segment& seg, int half_width) {
    return {moving_average(data.ud, seg, half_width), moving_average(data.uq, seg, half_width),
            moving_average(data.id, seg, half_width), moving_average(data.iq, seg, half_width),
            moving_average(data.omega, seg, half_width)};
}

// The unit current vector i / |i|: the direction of the dead-time voltage (0 at zero current).
void unit_current(double id, double iq, double& sd, double& sq) {
    const double norm = std::hypot(id, iq);
    sd = norm > 0.0 ? id / norm : 0.0;
    sq = norm > 0.0 ? iq / norm : 0.0;
}

} // namespace

LinearModel dynamic_model(const std::vector<Dataset>& datasets, const std::vector<std::string>& sources,
                          const DynamicModelOptions& options) {
    if (datasets.size() != sources.size())
        throw std::invalid_argument("pmsm: dynamic model given " + std::to_string(datasets.size()) +
                                    " datasets but " + std::to_string(sources.size()) + " source names");
    if (datasets.empty())
        throw std::invalid_argument("pmsm: the dynamic model needs at least one dataset");
    if (options.smoothing < 0)
        throw std::invalid_argument("pmsm: the smoothing half-width must be >= 0, not " +
                                    std::to_string(options.smoothing));
    const Eigen::Index k = options.fit_dead_time ? 5 : 4;

    // First pass: the segments of each dataset and the number of equations, so A is sized once.
    std::vector<std::vector<Segment>> segments(datasets.size());
    std::vector<double> periods(datasets.size());
    Eigen::Index n = 0;
    for (std::size_t s = 0; s < datasets.size(); ++s) {
        const Dataset& data = datasets[s];
        segments[s] = contiguous_segments(data, sampling_period(data, sources[s]));
        Eigen::Index pairs = 0;
        double span = 0.0;
        for (const Segment& seg : segments[s]) {
            pairs += static_cast<Eigen::Index>(seg.size()) - 1;
            span += data.t[seg.end - 1] - data.t[seg.begin];
        }
        if (pairs == 0)
            throw std::invalid_argument(sources[s] +
                                        ": no two consecutive rows one sampling period apart, so "
                                        "the dynamic model has no current derivative to use");
        // The period as the mean step over whole segments rather than the median single step: times
        // logged to 6-10 digits make one step ~1e-13 off (e.g. 0.3351 - 0.3350), which on clean data
        // moves f* by ~1e-9 relative, since Ts scales only the derivative part of the Ld and Lq
        // columns; over a segment of n steps that rounding is divided by n.
        periods[s] = span / static_cast<double>(pairs);
        n += pairs;
    }

    LinearModel model;
    model.A.setZero(2 * n, k);
    model.b.resize(2 * n);
    model.parameter_names = {"Rs", "Ld", "Lq", "psi"};
    if (options.fit_dead_time)
        model.parameter_names.emplace_back("Vdt");
    model.d_rows = n;
    model.run_starts.clear();

    Eigen::Index e = 0; // equation index within an axis
    for (std::size_t s = 0; s < datasets.size(); ++s) {
        const double Ts = periods[s];
        for (const Segment& seg : segments[s]) {
            if (seg.size() < 2)
                continue;
            model.run_starts.push_back(e);
            const Signals x = segment_signals(datasets[s], seg, options.smoothing);
            for (std::size_t i = 0; i + 1 < seg.size(); ++i, ++e) {
                const std::size_t j = i + 1;
                const double m_d = 0.5 * (x.id[i] + x.id[j]);
                const double m_q = 0.5 * (x.iq[i] + x.iq[j]);
                const double w_m = 0.5 * (x.omega[i] + x.omega[j]);
                const double w_iq = 0.5 * (x.omega[i] * x.iq[i] + x.omega[j] * x.iq[j]);
                const double w_id = 0.5 * (x.omega[i] * x.id[i] + x.omega[j] * x.id[j]);
                auto d = model.A.row(e);
                auto q = model.A.row(n + e);
                d(0) = row_factor * m_d;
                d(1) = row_factor * (x.id[j] - x.id[i]) / Ts;
                d(2) = -row_factor * w_iq;
                q(0) = row_factor * m_q;
                q(1) = row_factor * w_id;
                q(2) = row_factor * (x.iq[j] - x.iq[i]) / Ts;
                q(3) = row_factor * w_m;
                if (options.fit_dead_time) {
                    double sd0 = 0, sq0 = 0, sd1 = 0, sq1 = 0;
                    unit_current(x.id[i], x.iq[i], sd0, sq0);
                    unit_current(x.id[j], x.iq[j], sd1, sq1);
                    d(4) = row_factor * 0.5 * (sd0 + sd1);
                    q(4) = row_factor * 0.5 * (sq0 + sq1);
                }
                model.b[e] = row_factor * x.ud[i];
                model.b[n + e] = row_factor * x.uq[i];
                if (!d.allFinite() || !q.allFinite() || !std::isfinite(model.b[e]) ||
                    !std::isfinite(model.b[n + e]))
                    throw std::invalid_argument(
                        sources[s] + ": data row " + std::to_string(seg.begin + i) +
                        " (counting from 0) gives a non-finite dynamic equation (values too large or "
                        "not numbers)");
            }
        }
    }
    return model;
}

double dead_time_voltage(const Dataset& data) {
    double vdc = 0, dead = 0, ts = 0;
    const std::string* v = data.find_metadata("Vdc");
    const std::string* d = data.find_metadata("deadtime_s");
    const std::string* t = data.find_metadata("Ts");
    if (v == nullptr || d == nullptr || t == nullptr || !parse_real(*v, vdc) || !parse_real(*d, dead) ||
        !parse_real(*t, ts) || !(ts > 0.0))
        return 0.0;
    return 4.0 / std::numbers::pi * vdc * dead / ts;
}

} // namespace mhb::pmsm
