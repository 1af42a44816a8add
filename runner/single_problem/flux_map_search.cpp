#include "runner/single_problem/flux_map_search.hpp"

#include <cstddef>
#include <limits>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <optional>

namespace mhb {

FluxMapSearch search_flux_map(const fluxmap::CurrentMap& map, const Box& box,
                              const fluxmap::FitOptions& options, int threads) {
    const std::vector<Eigen::VectorXd> starts = fluxmap::multistart_points(box, options.starts, options.seed);
    std::vector<fluxmap::FitResult> ends(starts.size());
    std::optional<tbb::global_control> limit;
    if (threads > 0)
        limit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    tbb::parallel_for(std::size_t{0}, starts.size(), [&](std::size_t s) {
        ends[s] = fluxmap::fit_from(map, box, starts[s], options.max_iterations);
    });
    FluxMapSearch out;
    out.best.f = std::numeric_limits<double>::infinity();
    for (const fluxmap::FitResult& end : ends) {
        out.best.start_f.push_back(end.f);
        out.start_theta.push_back(end.theta);
        if (end.f < out.best.f) // strictly: the first of equal ends, as fit_multistart
            out.best.theta = end.theta, out.best.f = end.f;
    }
    return out;
}

} // namespace mhb
