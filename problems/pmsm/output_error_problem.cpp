#include "problems/pmsm/output_error_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "problems/core/parameters.hpp"

namespace mhb::pmsm {

namespace {

void require_model_size(const Eigen::VectorXd& x, Eigen::Index n, const std::string& what) {
    if (x.size() != n)
        throw std::invalid_argument("pmsm: " + what + " has " + std::to_string(x.size()) +
                                    " coordinates, the output-error model " + std::to_string(n));
}

} // namespace

OutputErrorProblem::OutputErrorProblem(OutputErrorModel model, Box bounds,
                                       std::optional<Eigen::VectorXd> truth,
                                       const std::vector<Eigen::VectorXd>& reference_starts)
    : model_(std::move(model)), box_(std::move(bounds)), truth_(std::move(truth)) {
    box_.validate("pmsm");
    const Eigen::Index n = model_.parameters();
    require_model_size(box_.lower, n, "the search box");
    if (truth_)
        require_model_size(*truth_, n, "the true parameter vector");
    for (const Eigen::VectorXd& start : reference_starts) {
        require_model_size(start, n, "a reference start");
        if (!start.allFinite())
            throw std::invalid_argument(
                "pmsm: a reference start of the output-error refinement is not finite");
    }
    best_.f = std::numeric_limits<double>::infinity();
    // In the order given, keeping the first of equal values, so the result does not depend on
    // anything but the arguments.
    for (const Eigen::VectorXd& start : reference_starts) {
        Refinement r = refine_output_error(model_, start, box_);
        if (r.f < best_.f)
            best_ = std::move(r);
    }
}

double OutputErrorProblem::evaluate(const Eigen::VectorXd& x) const {
    if (x.size() != model_.parameters())
        throw std::logic_error("pmsm: evaluate needs " + std::to_string(model_.parameters()) +
                               " coordinates");
    return model_.fitness(x);
}

std::optional<KnownOptimum> OutputErrorProblem::known_optimum() const {
    if (!std::isfinite(best_.f))
        return std::nullopt;
    // Through evaluate() itself, so f - f* is measured on one scale.
    return KnownOptimum{evaluate(best_.theta), best_.theta};
}

std::vector<std::string> OutputErrorProblem::warnings() const {
    std::vector<std::string> out;
    if (!std::isfinite(best_.f))
        return out;
    static const char* const spellings[] = {"rs", "ld", "lq", "psi", "vdt"};
    const std::vector<std::string> names = model_.parameter_names();
    for (Eigen::Index j = 0; j < model_.parameters(); ++j) {
        const double lo = box_.lower[j];
        const double hi = box_.upper[j];
        const double width = hi - lo;
        const double x = best_.theta[j];
        const bool at_lower = x - lo <= 1e-9 * width;
        const bool at_upper = hi - x <= 1e-9 * width;
        if (!at_lower && !at_upper)
            continue;
        // Widened by one width on the bound's side (not below 0 from a positive bound: these are
        // physical magnitudes).
        const double new_lo = at_lower ? (lo > 0.0 ? std::max(0.0, lo - width) : lo - width) : lo;
        const double new_hi = at_upper ? hi + width : hi;
        const auto j_index = static_cast<std::size_t>(j);
        out.push_back("pmsm: the best known optimum has " + names[j_index] + " = " + format_real(x) +
                      " on the " + (at_lower ? "lower" : "upper") + " bound of its search box [" +
                      format_real(lo) + ", " + format_real(hi) +
                      "], so optimisers will find the box, not the motor; widen it, e.g. " +
                      spellings[j_index] + "=" + format_real(new_lo) + ":" + format_real(new_hi));
    }
    return out;
}

} // namespace mhb::pmsm
