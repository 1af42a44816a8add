// The output-error identification model: simulate the dq currents from the measured voltages and
// speed with candidate parameters, and compare them with the measured currents,
//
//   f(theta) = sum over rows (id_sim - id)^2 + (iq_sim - iq)^2        (A^2),
//
// segment by segment (segments.hpp): each contiguous run of rows starts from its measured
// currents, and the voltage of row k is held over [t_k, t_k + Ts) while the speed moves linearly
// from omega[k] to omega[k + 1] (the best the log says of it). The electrical dq equations are
// integrated by classical RK4 with `substeps` steps per period, as the drive simulator does:
//
//   did/dt = (ud - Vdt sd - Rs id + w Lq iq) / Ld,  diq/dt = (uq - Vdt sq - Rs iq - w Ld id - w psi) / Lq
//
// with (sd, sq) = i / |i| of the simulated current when the dead-time voltage Vdt is fitted (a
// fifth parameter; see dynamic_model.hpp), taken at the start of each RK4 step and held over it as
// the drive simulator holds its dead-time error. Nonlinear in (Rs, Ld, Lq): no closed-form
// optimum, and no guarantee of a single minimum (though on the shared `_tr` files 201 starts in a
// wide box all reached the same one; tests/data/pmsm/README.md). Every evaluation is a simulation
// of every row (O(rows x substeps)); the state's sums are Kahan-compensated, so that rounding does
// not blur f near a clean optimum, where its residuals are microamperes of ampere-sized currents.
//
// A simulation diverges when a current is not finite or exceeds max_dataset_magnitude (1e9 A,
// the dataset reader's sanity bound) at the end of a period: RK4 is unstable once h (Rs / L) or h w passes
// ~2.8, which a search box reaching down to L -> 0 always allows, and stopping there keeps such points cheap.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "problems/pmsm/dataset.hpp"
#include "problems/pmsm/segments.hpp"
#include "problems/problem.hpp"

namespace mhb::pmsm {

struct OutputErrorOptions {
    bool fit_dead_time = false; // a fifth parameter Vdt (V)
    int substeps = 2;           // RK4 steps per sampling period, 1..1000
};

class OutputErrorModel {
public:
    // `sources` name the datasets in errors, one each. Throws std::invalid_argument when no
    // segment has two rows, a value is not finite (naming the source), or substeps is outside
    // [1, 1000].
    OutputErrorModel(const std::vector<Dataset>& datasets, const std::vector<std::string>& sources,
                     const OutputErrorOptions& options = {});

    [[nodiscard]] Eigen::Index parameters() const { return fit_dead_time_ ? 5 : 4; }
    [[nodiscard]] std::vector<std::string> parameter_names() const;
    // Rows compared (the first row of each segment is the initial condition and is not).
    [[nodiscard]] Eigen::Index rows() const;

    // f(theta); +inf when the simulation diverges (see above) or theta has a non-finite entry or
    // a non-positive inductance. No allocation; safe to call from many threads at once. Throws
    // std::logic_error when theta has not parameters() coordinates.
    [[nodiscard]] double fitness(const Eigen::Ref<const Eigen::VectorXd>& theta) const;
    // The residuals (id_sim - id for every compared row, then iq_sim - iq), resized to 2 rows();
    // every entry +inf where fitness() is, so r.squaredNorm() is fitness(theta) up to the order
    // of summation.
    void residuals(const Eigen::Ref<const Eigen::VectorXd>& theta, Eigen::VectorXd& r) const;
    // The simulated currents of every row of dataset `which` (the first row of a segment is its
    // measurement), for comparing with the drive simulator. Rows after a divergence are NaN.
    void simulate(const Eigen::Ref<const Eigen::VectorXd>& theta, std::size_t which, std::vector<double>& id,
                  std::vector<double>& iq) const;

    // Out of line: Series is complete only in output_error.cpp.
    ~OutputErrorModel();
    OutputErrorModel(const OutputErrorModel&);
    OutputErrorModel(OutputErrorModel&&) noexcept;
    OutputErrorModel& operator=(const OutputErrorModel&);
    OutputErrorModel& operator=(OutputErrorModel&&) noexcept;

private:
    struct Series; // one dataset's columns and segments
    std::vector<Series> series_;
    bool fit_dead_time_ = false;
    int substeps_ = 2;
    Eigen::Index rows_ = 0;
};

// A local refinement of theta by projected Levenberg-Marquardt on the residuals, staying inside
// `box`: how the problem finds its best known optimum from good starts. The start is clamped into
// the box; the Jacobian is by central differences with steps of 1e-6 of each box width (one-sided
// at a bound); a parameter on a bound whose gradient points out of the box is held there (an
// active set), the others take the damped Gauss-Newton step, clamped into the box. Deterministic:
// the same model, start and box give the same result bit for bit. A local method: it finds the
// minimum of the basin the start lies in, nothing more. Throws std::invalid_argument when the
// start or the box has not model.parameters() coordinates.
struct Refinement {
    Eigen::VectorXd theta;
    double f = 0.0;     // fitness(theta); +inf when the start (clamped) could not be simulated
    int iterations = 0; // Jacobians computed
};
Refinement refine_output_error(const OutputErrorModel& model, const Eigen::VectorXd& start, const Box& box,
                               int max_iterations = 100);

} // namespace mhb::pmsm
