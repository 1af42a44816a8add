// A fit's current errors binned over the (i_d, i_q) plane: a residual map small enough for a
// terminal, where a model's systematic misfit (at high saturation, around i_d = 0, ...) shows as
// a region, not as one number.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "problems/fluxmap/flux_map.hpp"

namespace mhb::fluxmap {

struct ResidualMap {
    std::vector<double> d_edges, q_edges; // bin edges, A: columns + 1 and rows + 1 values
    Eigen::MatrixXd rms; // RMS of |e_k| (A) of the points in each bin; rows by i_q, columns by
                         // i_d, both ascending; NaN for an empty bin
    Eigen::MatrixXi points;
};

// Equal-width bins over the map's current range, at most `columns` x `rows` (fewer when the map
// has fewer distinct values on an axis). `residuals`: 2 n entries, d errors then q errors.
ResidualMap residual_map(const FluxMap& map, const Eigen::VectorXd& residuals, int columns, int rows);

} // namespace mhb::fluxmap
