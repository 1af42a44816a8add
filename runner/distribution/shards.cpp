#include "runner/distribution/shards.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <numeric>
#include <stdexcept>

#include "runner/study/calibration.hpp"

namespace mhb {

ShardSpec parse_shard(std::string_view text) {
    const auto fail = [&] {
        throw std::invalid_argument("shard = " + std::string(text) +
                                    " is not i/n with 1 <= i <= n <= 100000 (e.g. --shard 2/8)");
    };
    const auto slash = text.find('/');
    if (slash == std::string_view::npos)
        fail();
    ShardSpec shard;
    const auto read = [&](std::string_view part, int& out) {
        const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
        if (part.empty() || ec != std::errc() || ptr != part.data() + part.size())
            fail();
    };
    read(text.substr(0, slash), shard.index);
    read(text.substr(slash + 1), shard.count);
    if (shard.count < 1 || shard.count > 100000 || shard.index < 1 || shard.index > shard.count)
        fail();
    return shard;
}

std::string shard_text(const ShardSpec& shard) {
    return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

std::vector<double> estimated_run_costs(const PreparedStudy& study) {
    const std::size_t algorithms = study.algorithms.size();
    const std::size_t problems = study.problems.size();
    const std::int64_t runs = study.study.runs;
    std::vector<double> cost(static_cast<std::size_t>(study.run_count()), 0.0);
    // Evaluations of one run per (budget, algorithm, dimension): iteration budgets are calibrated
    // once per dimension on the first problem that has it (a deterministic run).
    std::map<std::tuple<std::size_t, std::size_t, Eigen::Index>, double> evaluations;
    for (std::size_t b = 0; b < study.study.budgets.size(); ++b) {
        for (std::size_t p = 0; p < problems; ++p) {
            const Eigen::Index dimension = study.problems[p].problem->dimension();
            const Budget budget = study.budget_for(b, p);
            for (std::size_t a = 0; a < algorithms; ++a) {
                const auto first = static_cast<std::int64_t>((b * problems + p) * algorithms + a) * runs;
                const auto key = std::make_tuple(b, a, dimension);
                if (evaluations.count(key) == 0) {
                    const double per_run =
                        budget.max_iterations
                            ? extrapolated_evaluations(short_run(study.request(first), 100000), budget)
                            : static_cast<double>(budget.max_evaluations.value_or(1));
                    evaluations[key] = std::max(per_run, 1.0);
                }
                for (std::int64_t r = 0; r < runs; ++r)
                    cost[static_cast<std::size_t>(first + r)] =
                        evaluations[key] * static_cast<double>(dimension);
            }
        }
    }
    return cost;
}

std::vector<std::vector<std::int64_t>> shard_run_ids(const PreparedStudy& study, int count) {
    if (count < 1)
        throw std::invalid_argument("shard count " + std::to_string(count) + " is outside [1, 100000]");
    const std::vector<double> cost = estimated_run_costs(study);
    std::vector<std::int64_t> order(cost.size());
    std::iota(order.begin(), order.end(), std::int64_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::int64_t a, std::int64_t b) {
        return cost[static_cast<std::size_t>(a)] > cost[static_cast<std::size_t>(b)];
    });
    std::vector<std::vector<std::int64_t>> shards(static_cast<std::size_t>(count));
    std::vector<double> load(static_cast<std::size_t>(count), 0.0);
    for (const std::int64_t id : order) {
        const auto lightest =
            static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
        shards[lightest].push_back(id);
        load[lightest] += cost[static_cast<std::size_t>(id)];
    }
    for (auto& s : shards)
        std::sort(s.begin(), s.end());
    return shards;
}

} // namespace mhb
