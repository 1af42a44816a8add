// The binned residual map of residual_map.hpp.
#include "problems/fluxmap/residual_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace mhb::fluxmap {
namespace {

std::vector<double> edges(const Eigen::ArrayXd& values, int most) {
    const std::set<double> distinct(values.begin(), values.end());
    const int bins = std::max(1, std::min(most, static_cast<int>(distinct.size())));
    const double lo = values.minCoeff(), hi = values.maxCoeff();
    std::vector<double> out;
    for (int b = 0; b <= bins; ++b)
        out.push_back(lo + (hi - lo) * b / bins);
    return out;
}

int bin_of(const std::vector<double>& e, double value) {
    const auto bins = static_cast<int>(e.size()) - 1;
    if (e.back() == e.front())
        return 0;
    const auto b = static_cast<int>(std::floor((value - e.front()) / (e.back() - e.front()) * bins));
    return std::clamp(b, 0, bins - 1); // the top edge belongs to the last bin
}

} // namespace

ResidualMap residual_map(const FluxMap& map, const Eigen::VectorXd& residuals, int columns, int rows) {
    ResidualMap out;
    out.d_edges = edges(map.i_d, columns);
    out.q_edges = edges(map.i_q, rows);
    const auto nc = static_cast<Eigen::Index>(out.d_edges.size() - 1);
    const auto nr = static_cast<Eigen::Index>(out.q_edges.size() - 1);
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(nr, nc);
    out.points = Eigen::MatrixXi::Zero(nr, nc);
    const Eigen::Index n = map.size();
    for (Eigen::Index k = 0; k < n; ++k) {
        const int c = bin_of(out.d_edges, map.i_d[k]);
        const int r = bin_of(out.q_edges, map.i_q[k]);
        sum(r, c) += residuals[k] * residuals[k] + residuals[n + k] * residuals[n + k];
        out.points(r, c) += 1;
    }
    out.rms.resize(nr, nc);
    for (Eigen::Index r = 0; r < nr; ++r)
        for (Eigen::Index c = 0; c < nc; ++c)
            out.rms(r, c) = out.points(r, c) > 0 ? std::sqrt(sum(r, c) / out.points(r, c))
                                                 : std::numeric_limits<double>::quiet_NaN();
    return out;
}

} // namespace mhb::fluxmap
