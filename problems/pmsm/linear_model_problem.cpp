#include "problems/pmsm/linear_model_problem.hpp"

#include <Eigen/QR>
#include <cctype>
#include <cstdio>
#include <stdexcept>

namespace mhb::pmsm {
namespace {

constexpr Eigen::Index max_parameters = 5; // the capacity of the expansion's fixed-size members

std::string short_number(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", x);
    return buffer;
}

std::string lowercase(std::string s) {
    for (char& c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

} // namespace

LinearModelProblem::LinearModelProblem(LinearModel model, Box bounds, std::optional<Eigen::VectorXd> truth)
    : model_(std::move(model)), box_(std::move(bounds)), truth_(std::move(truth)) {
    const Eigen::Index k = model_.parameters();
    box_.validate("pmsm");
    if (k > max_parameters)
        throw std::invalid_argument("pmsm: a linear model has at most " + std::to_string(max_parameters) +
                                    " parameters, not " + std::to_string(k));
    if (box_.dimension() != k)
        throw std::invalid_argument("pmsm: bounds must have " + std::to_string(k) +
                                    " coordinates, one per parameter");
    if (truth_ && truth_->size() != k)
        throw std::invalid_argument("pmsm: the true parameters have " + std::to_string(truth_->size()) +
                                    " values for " + std::to_string(k) + " parameters");
    if (model_.parameter_names.empty())
        for (Eigen::Index j = 0; j < k; ++j)
            model_.parameter_names.push_back("theta" + std::to_string(j));
    fit_ = fit_linear_model(model_, &box_);
    if (fit_.rank < k) {
        std::string names;
        for (Eigen::Index j = 0; j < k; ++j)
            if (!fit_.determined[static_cast<std::size_t>(j)])
                names += (names.empty() ? "" : ", ") + model_.parameter_names[static_cast<std::size_t>(j)];
        throw std::invalid_argument(
            "pmsm: the data do not determine " + names + " (the equations have rank " +
            std::to_string(fit_.rank) + " for " + std::to_string(k) +
            " parameters: their columns are linearly dependent, so the data need more excitation, "
            "e.g. a current change on each axis)");
    }

    // The expansion about the least-squares optimum (as expanded_fitness.hpp): g0 from the
    // residuals there, R the triangular factor of A (Householder QR, so |R d|^2 = d^T A^T A d
    // without forming A^T A).
    theta0_ = fit_.theta;
    f0_ = model_.fitness(fit_.theta);
    g0_ = -(model_.A.transpose() * (model_.b - model_.A * fit_.theta));
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(model_.A);
    r_ = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>();
}

double LinearModelProblem::evaluate(const Eigen::VectorXd& x) const {
    const Eigen::Index k = theta0_.size();
    if (x.size() != k)
        throw std::logic_error("pmsm: evaluate needs " + std::to_string(k) + " coordinates");
    // Plain loops over fixed-capacity arrays: no temporaries, so no allocation.
    double d[max_parameters];
    double linear = 0.0;
    for (Eigen::Index j = 0; j < k; ++j) {
        d[j] = x[j] - theta0_[j];
        linear += g0_[j] * d[j];
    }
    double quadratic = 0.0;
    for (Eigen::Index i = 0; i < k; ++i) {
        double row = 0.0;
        for (Eigen::Index j = i; j < k; ++j)
            row += r_(i, j) * d[j];
        quadratic += row * row;
    }
    return f0_ + 2.0 * linear + quadratic;
}

std::optional<KnownOptimum> LinearModelProblem::known_optimum() const {
    // f* through evaluate() itself, so f - f* is measured on one scale.
    const Eigen::VectorXd x = fit_.box_theta;
    return KnownOptimum{evaluate(x), x};
}

std::vector<std::string> LinearModelProblem::warnings() const {
    std::vector<std::string> out;
    for (Eigen::Index j = 0; j < model_.parameters(); ++j) {
        const int side = fit_.active_bound[static_cast<std::size_t>(j)];
        if (side == 0)
            continue;
        const std::string& name = model_.parameter_names[static_cast<std::size_t>(j)];
        const double value = fit_.theta[j], lo = box_.lower[j], hi = box_.upper[j];
        std::string box = "["; // built by appending: GCC 12's -Wrestrict misfires on `"[" + std::string`
        box.append(short_number(lo)).append(", ").append(short_number(hi)).append("]");
        const std::string bound = side < 0 ? "lower" : "upper";
        const std::string advice = "widen the bound (" + lowercase(name) + "=lo:hi)";
        if (value < lo || value > hi)
            out.push_back("the least-squares optimum has " + name + " = " + short_number(value) +
                          ", outside the search box " + box + ": f* is the box-constrained optimum, on the " +
                          bound + " bound of " + name + "; " + advice);
        else // inside its own interval, but pushed to a bound by the others' bounds (correlation)
            out.push_back("the least-squares optimum has " + name + " = " + short_number(value) + " inside " +
                          box +
                          ", but the box cuts the optimum elsewhere and f* (the box-constrained "
                          "optimum) has " +
                          name + " on its " + bound + " bound; " + advice);
    }
    return out;
}

} // namespace mhb::pmsm
