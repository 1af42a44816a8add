#include "problems/pmsm/output_error_identification.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace mhb::pmsm {

LinearModel linearise_residuals(const OutputErrorProblem& problem, const Eigen::VectorXd& theta0) {
    const OutputErrorModel& model = problem.model();
    const Eigen::Index k = theta0.size();
    Eigen::VectorXd r0, plus, minus;
    model.residuals(theta0, r0);
    Eigen::MatrixXd J(r0.size(), k);
    for (Eigen::Index j = 0; j < k; ++j) {
        const double h = 1e-6 * (problem.bounds().upper[j] - problem.bounds().lower[j]);
        Eigen::VectorXd x = theta0;
        x[j] = theta0[j] + h;
        model.residuals(x, plus);
        x[j] = theta0[j] - h;
        model.residuals(x, minus);
        J.col(j) = (plus - minus) / (2.0 * h);
    }
    LinearModel out;
    out.A = -J;
    out.b = r0 - J * theta0;
    out.parameter_names = model.parameter_names();
    out.d_rows = model.rows();
    return out;
}

OutputIdentification summarise_seeds(const OutputErrorProblem& problem, std::vector<Eigen::VectorXd> seed_x,
                                     std::vector<double> seed_f) {
    const Eigen::Index k = problem.dimension();
    if (seed_x.empty() || seed_x.size() != seed_f.size() ||
        std::any_of(seed_x.begin(), seed_x.end(), [k](const Eigen::VectorXd& x) { return x.size() != k; }))
        throw std::invalid_argument("summarise_seeds: needs one point of the problem's dimension per value");
    OutputIdentification out;
    out.seed_x = std::move(seed_x);
    out.seed_f = std::move(seed_f);
    const auto best =
        static_cast<std::size_t>(std::min_element(out.seed_f.begin(), out.seed_f.end()) - out.seed_f.begin());
    out.best_x = out.seed_x[best];
    out.best_f = out.seed_f[best];
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(k);
    for (const auto& x : out.seed_x)
        mean += x;
    mean /= static_cast<double>(out.seed_x.size());
    out.spread = Eigen::VectorXd::Zero(k);
    for (const auto& x : out.seed_x)
        out.spread += (x - mean).cwiseAbs2();
    out.spread =
        (out.spread / std::max<double>(1.0, static_cast<double>(out.seed_x.size()) - 1.0)).cwiseSqrt();
    for (const double f : out.seed_f)
        out.seeds_at_best += f <= out.best_f + 1e-6 * std::fabs(out.best_f) ? 1 : 0;
    out.linearised = linearise_residuals(problem, out.best_x);
    return out;
}

} // namespace mhb::pmsm
