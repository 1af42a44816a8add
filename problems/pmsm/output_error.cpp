#include "problems/pmsm/output_error.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "problems/pmsm/dataset_csv.hpp"

namespace mhb::pmsm {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// The candidate parameters with the two divisions of the derivative turned into products once,
// not 2 x 4 x substeps times per row.
struct Params {
    double Rs = 0, Ld = 0, Lq = 0, psi = 0, Vdt = 0;
    double inv_Ld = 0, inv_Lq = 0;
};

// False when theta cannot be simulated (a non-finite entry or a non-positive inductance).
bool make_params(const Eigen::Ref<const Eigen::VectorXd>& theta, bool dead_time, Params& p) {
    if (!theta.allFinite() || !(theta[1] > 0.0) || !(theta[2] > 0.0))
        return false;
    p.Rs = theta[0];
    p.Ld = theta[1];
    p.Lq = theta[2];
    p.psi = theta[3];
    p.Vdt = dead_time ? theta[4] : 0.0;
    p.inv_Ld = 1.0 / p.Ld;
    p.inv_Lq = 1.0 / p.Lq;
    return true;
}

// The electrical part of the drive simulator's derivative (drive_simulator.cpp), at speed w.
inline void derivative(const Params& p, double vd, double vq, double w, double id, double iq, double& did,
                       double& diq) {
    did = (vd - p.Rs * id + w * p.Lq * iq) * p.inv_Ld;
    diq = (vq - p.Rs * iq - w * p.Ld * id - w * p.psi) * p.inv_Lq;
}

// One sampling period of length T: (ud, uq) held, the speed moving linearly from w0 to w1, by
// n classical RK4 steps. The stage speeds are the line's values at the stage times, so a
// constant speed gives the drive simulator's steps.
inline void integrate_period(const Params& p, double ud, double uq, double w0, double w1, double T, int n,
                             double& id, double& iq, double& id_lo, double& iq_lo) {
    const double h = T / n;
    const double dw = (w1 - w0) / n;
    for (int s = 0; s < n; ++s) {
        const double wa = w0 + dw * s;
        const double wm = wa + 0.5 * dw;
        const double wb = wa + dw;
        double vd = ud;
        double vq = uq;
        if (p.Vdt != 0.0) {
            // The dead-time voltage opposes the current; held over the step from its start, as
            // the drive simulator holds its per-phase error. Not std::hypot, which would double
            // the cost of a step: the squares overflow only in a simulation that has diverged
            // anyway, and the non-finite current that follows is caught at the period's end.
            const double magnitude = std::sqrt(id * id + iq * iq);
            if (magnitude > 0.0) {
                vd -= p.Vdt * id / magnitude;
                vq -= p.Vdt * iq / magnitude;
            }
        }
        double k1d = 0, k1q = 0, k2d = 0, k2q = 0, k3d = 0, k3q = 0, k4d = 0, k4q = 0;
        derivative(p, vd, vq, wa, id, iq, k1d, k1q);
        derivative(p, vd, vq, wm, id + 0.5 * h * k1d, iq + 0.5 * h * k1q, k2d, k2q);
        derivative(p, vd, vq, wm, id + 0.5 * h * k2d, iq + 0.5 * h * k2q, k3d, k3q);
        derivative(p, vd, vq, wb, id + h * k3d, iq + h * k3q, k4d, k4q);
        // Kahan-compensated: the increments are ~1e-2 of the currents, and plain sums leave a
        // rounding walk of ~1e-14 A in the state, which made f itself uncertain by 1e-9 relative
        // on the clean shared files (2e-11 with the compensation, for ~10 % more time).
        const double yd = h / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d) - id_lo;
        const double yq = h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q) - iq_lo;
        const double td = id + yd;
        const double tq = iq + yq;
        id_lo = (td - id) - yd;
        iq_lo = (tq - iq) - yq;
        id = td;
        iq = tq;
    }
}

// Written as a negated comparison so that NaN counts as diverged too.
inline bool diverged(double id, double iq) {
    return !(std::fabs(id) <= max_dataset_magnitude && std::fabs(iq) <= max_dataset_magnitude);
}

} // namespace

struct OutputErrorModel::Series {
    std::vector<double> t, ud, uq, id, iq, omega;
    std::vector<Segment> segments;

    // Simulates every segment from its measured first row and hands each later row to
    // sink(k, id_sim, iq_sim) in order. False (and the rest of the rows unvisited) on divergence.
    template <class Sink> bool walk(const Params& p, int substeps, Sink&& sink) const {
        for (const Segment& segment : segments) {
            double i_d = id[segment.begin];
            double i_q = iq[segment.begin];
            double lo_d = 0.0;
            double lo_q = 0.0;
            for (std::size_t k = segment.begin; k + 1 < segment.end; ++k) {
                integrate_period(p, ud[k], uq[k], omega[k], omega[k + 1], t[k + 1] - t[k], substeps, i_d, i_q,
                                 lo_d, lo_q);
                if (diverged(i_d, i_q))
                    return false;
                sink(k + 1, i_d, i_q);
            }
        }
        return true;
    }
};

OutputErrorModel::OutputErrorModel(const std::vector<Dataset>& datasets,
                                   const std::vector<std::string>& sources, const OutputErrorOptions& options)
    : fit_dead_time_(options.fit_dead_time), substeps_(options.substeps) {
    if (options.substeps < 1 || options.substeps > 1000)
        throw std::invalid_argument("pmsm output-error model: substeps = " +
                                    std::to_string(options.substeps) + " is outside [1, 1000]");
    if (sources.size() != datasets.size())
        throw std::invalid_argument("pmsm output-error model: " + std::to_string(datasets.size()) +
                                    " datasets but " + std::to_string(sources.size()) + " source names");
    series_.reserve(datasets.size());
    for (std::size_t i = 0; i < datasets.size(); ++i) {
        const Dataset& data = datasets[i];
        for (const std::vector<double>* column :
             {&data.t, &data.ud, &data.uq, &data.id, &data.iq, &data.omega})
            for (const double v : *column)
                if (!std::isfinite(v))
                    throw std::invalid_argument(sources[i] + ": a non-finite value; the output-error model "
                                                             "cannot simulate through it");
        Series s{data.t, data.ud, data.uq, data.id, data.iq, data.omega, {}};
        if (data.size() >= 2)
            s.segments = contiguous_segments(data, sampling_period(data, sources[i]));
        for (const Segment& segment : s.segments)
            rows_ += static_cast<Eigen::Index>(segment.size()) - 1;
        series_.push_back(std::move(s));
    }
    if (rows_ == 0) {
        std::string names;
        for (const std::string& source : sources)
            names += (names.empty() ? "" : ", ") + source;
        throw std::invalid_argument("pmsm output-error model: " + (names.empty() ? "no dataset" : names) +
                                    " has no two consecutive rows one sampling period apart to simulate");
    }
}

OutputErrorModel::~OutputErrorModel() = default;
OutputErrorModel::OutputErrorModel(const OutputErrorModel&) = default;
OutputErrorModel::OutputErrorModel(OutputErrorModel&&) noexcept = default;
OutputErrorModel& OutputErrorModel::operator=(const OutputErrorModel&) = default;
OutputErrorModel& OutputErrorModel::operator=(OutputErrorModel&&) noexcept = default;

std::vector<std::string> OutputErrorModel::parameter_names() const {
    std::vector<std::string> names{"Rs", "Ld", "Lq", "psi"};
    if (fit_dead_time_)
        names.emplace_back("Vdt");
    return names;
}

Eigen::Index OutputErrorModel::rows() const {
    return rows_;
}

namespace {

void require_theta_size(const Eigen::Ref<const Eigen::VectorXd>& theta, Eigen::Index n) {
    if (theta.size() != n)
        throw std::logic_error("pmsm output-error model: theta has " + std::to_string(theta.size()) +
                               " coordinates, the model " + std::to_string(n));
}

} // namespace

double OutputErrorModel::fitness(const Eigen::Ref<const Eigen::VectorXd>& theta) const {
    require_theta_size(theta, parameters());
    Params p;
    if (!make_params(theta, fit_dead_time_, p))
        return infinity;
    double f = 0.0;
    for (const Series& s : series_) {
        const bool ok = s.walk(p, substeps_, [&](std::size_t k, double i_d, double i_q) {
            const double ed = i_d - s.id[k];
            const double eq = i_q - s.iq[k];
            f += ed * ed + eq * eq;
        });
        if (!ok)
            return infinity;
    }
    return f;
}

void OutputErrorModel::residuals(const Eigen::Ref<const Eigen::VectorXd>& theta, Eigen::VectorXd& r) const {
    require_theta_size(theta, parameters());
    r.resize(2 * rows_);
    Params p;
    if (!make_params(theta, fit_dead_time_, p)) {
        r.setConstant(infinity);
        return;
    }
    Eigen::Index row = 0;
    for (const Series& s : series_) {
        const bool ok = s.walk(p, substeps_, [&](std::size_t k, double i_d, double i_q) {
            r[row] = i_d - s.id[k];
            r[rows_ + row] = i_q - s.iq[k];
            ++row;
        });
        if (!ok) {
            r.setConstant(infinity);
            return;
        }
    }
}

void OutputErrorModel::simulate(const Eigen::Ref<const Eigen::VectorXd>& theta, std::size_t which,
                                std::vector<double>& id, std::vector<double>& iq) const {
    require_theta_size(theta, parameters());
    if (which >= series_.size())
        throw std::logic_error("pmsm output-error model: dataset " + std::to_string(which) + " of " +
                               std::to_string(series_.size()));
    const Series& s = series_[which];
    id.assign(s.t.size(), std::numeric_limits<double>::quiet_NaN());
    iq.assign(s.t.size(), std::numeric_limits<double>::quiet_NaN());
    for (const Segment& segment : s.segments) {
        id[segment.begin] = s.id[segment.begin];
        iq[segment.begin] = s.iq[segment.begin];
    }
    Params p;
    if (!make_params(theta, fit_dead_time_, p))
        return;
    (void)s.walk(p, substeps_, [&](std::size_t k, double i_d, double i_q) {
        id[k] = i_d;
        iq[k] = i_q;
    });
}

namespace {

// Central differences have error O(h^2) + eps |r| / h; with h = 1e-6 of the box width both are
// ~1e-10 relative for a parameter of the width's order, far below what the iteration needs.
constexpr double relative_step = 1e-6;

// J = dr/dtheta by central differences, one-sided where a step would leave the box or the
// simulation diverges on one side; a column that cannot be formed at all is left zero, so the
// parameter stays put this iteration.
void jacobian(const OutputErrorModel& model, const Eigen::VectorXd& x, const Eigen::VectorXd& r,
              const Box& box, Eigen::MatrixXd& J, Eigen::VectorXd& work_plus, Eigen::VectorXd& work_minus) {
    const Eigen::Index n = x.size();
    J.resize(r.size(), n);
    Eigen::VectorXd probe = x;
    for (Eigen::Index j = 0; j < n; ++j) {
        const double h = relative_step * (box.upper[j] - box.lower[j]);
        const double up = std::min(x[j] + h, box.upper[j]);
        const double down = std::max(x[j] - h, box.lower[j]);
        bool have_plus = up > x[j];
        bool have_minus = down < x[j];
        if (have_plus) {
            probe[j] = up;
            model.residuals(probe, work_plus);
            have_plus = work_plus.allFinite();
        }
        if (have_minus) {
            probe[j] = down;
            model.residuals(probe, work_minus);
            have_minus = work_minus.allFinite();
        }
        probe[j] = x[j];
        if (have_plus && have_minus)
            J.col(j) = (work_plus - work_minus) / (up - down);
        else if (have_plus)
            J.col(j) = (work_plus - r) / (up - x[j]);
        else if (have_minus)
            J.col(j) = (r - work_minus) / (x[j] - down);
        else
            J.col(j).setZero();
    }
}

} // namespace

Refinement refine_output_error(const OutputErrorModel& model, const Eigen::VectorXd& start, const Box& box,
                               int max_iterations) {
    const Eigen::Index n = model.parameters();
    if (start.size() != n || box.dimension() != n)
        throw std::invalid_argument(
            "pmsm output-error refinement: the start (" + std::to_string(start.size()) + ") and the box (" +
            std::to_string(box.dimension()) + ") need " + std::to_string(n) + " coordinates");
    box.validate("pmsm output-error refinement");

    Refinement out;
    out.theta = start.cwiseMax(box.lower).cwiseMin(box.upper);
    Eigen::VectorXd r, trial_r, work_plus, work_minus;
    model.residuals(out.theta, r);
    out.f = r.allFinite() ? r.squaredNorm() : infinity;
    if (!std::isfinite(out.f))
        return out;

    // Marquardt's damping, relative to the diagonal of J^T J (so invariant to the parameters'
    // units): lambda shrinks after a successful step and grows after a failed one.
    double lambda = 1e-3;
    Eigen::MatrixXd J;
    for (int iteration = 0; iteration < max_iterations && out.f > 0.0; ++iteration) {
        jacobian(model, out.theta, r, box, J, work_plus, work_minus);
        ++out.iterations;
        const Eigen::VectorXd g = J.transpose() * r;
        const Eigen::MatrixXd A = J.transpose() * J;

        // Free parameters: inside the box, or on a bound with the descent direction pointing in.
        std::vector<Eigen::Index> free;
        for (Eigen::Index j = 0; j < n; ++j) {
            const bool held = (out.theta[j] <= box.lower[j] && g[j] > 0.0) ||
                              (out.theta[j] >= box.upper[j] && g[j] < 0.0) || A(j, j) == 0.0;
            if (!held)
                free.push_back(j);
        }
        if (free.empty())
            break;
        const auto m = static_cast<Eigen::Index>(free.size());
        Eigen::MatrixXd Af(m, m);
        Eigen::VectorXd gf(m);
        for (Eigen::Index a = 0; a < m; ++a) {
            gf[a] = g[free[static_cast<std::size_t>(a)]];
            for (Eigen::Index b = 0; b < m; ++b)
                Af(a, b) = A(free[static_cast<std::size_t>(a)], free[static_cast<std::size_t>(b)]);
        }

        bool accepted = false;
        bool stalled = false;
        while (!accepted && !stalled) {
            Eigen::MatrixXd M = Af;
            M.diagonal() += lambda * Af.diagonal();
            const Eigen::VectorXd step = M.ldlt().solve(-gf);
            Eigen::VectorXd trial = out.theta;
            for (Eigen::Index a = 0; a < m; ++a)
                trial[free[static_cast<std::size_t>(a)]] += step[a];
            trial = trial.cwiseMax(box.lower).cwiseMin(box.upper);
            // A step below 1e-14 of the box in every coordinate changes nothing measurable.
            const double moved =
                ((trial - out.theta).array().abs() / (box.upper - box.lower).array()).maxCoeff();
            if (!step.allFinite() || moved <= 1e-14) {
                stalled = true;
                break;
            }
            model.residuals(trial, trial_r);
            const double trial_f = trial_r.allFinite() ? trial_r.squaredNorm() : infinity;
            if (trial_f < out.f) {
                accepted = true;
                const double decrease = out.f - trial_f;
                out.theta = trial;
                r.swap(trial_r);
                // Converged when the decrease is at the rounding level of f itself.
                stalled = decrease <= 1e-14 * out.f;
                out.f = trial_f;
                lambda = std::max(lambda * 0.3, 1e-15);
            } else {
                lambda *= 10.0;
                stalled = lambda > 1e16;
            }
        }
        if (stalled)
            break;
    }
    // fitness() sums in row order, the squared norm in Eigen's: report the value evaluate() gives.
    out.f = model.fitness(out.theta);
    return out;
}

} // namespace mhb::pmsm
