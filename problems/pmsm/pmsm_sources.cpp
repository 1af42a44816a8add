#include "problems/pmsm/pmsm_sources.hpp"

#include <set>
#include <stdexcept>

#include "problems/core/parameters.hpp"
#include "problems/core/rng.hpp"
#include "problems/core/text_excerpt.hpp"
#include "problems/pmsm/dataset_csv.hpp"

namespace mhb::pmsm {
namespace {

std::vector<std::string> split_plus(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto end = std::min(text.find('+', start), text.size());
        out.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

} // namespace

std::optional<Eigen::Vector4d> PmsmSources::nominal_parameters() const {
    for (const Dataset& d : datasets)
        if (auto theta = d.true_parameters())
            return theta;
    return std::nullopt;
}

PmsmSources read_sources(const std::string& joined_paths, const DatasetReadOptions& options) {
    PmsmSources out;
    std::set<std::string> seen;
    for (const std::string& path : split_plus(joined_paths)) {
        if (path.empty())
            throw std::invalid_argument("pmsm: data = " + value_excerpt(joined_paths) +
                                        " has an empty file name (join files with '+': a.csv+b.csv)");
        if (!seen.insert(path).second)
            throw std::invalid_argument("pmsm: data names " + quoted_excerpt(path) + " twice");
        DataFile file{path, ""};
        out.datasets.push_back(read_dataset_csv(path, options, &file.sha256));
        out.names.push_back(path);
        out.files.push_back(std::move(file));
    }
    return out;
}

std::vector<OperatingCondition> parse_conditions(const std::string& text) {
    if (text == "paper")
        return {{2500.0, 2.0}, {2500.0, 3.0}, {2000.0, 2.0}};
    std::vector<OperatingCondition> out;
    for (const std::string& item : split_plus(text)) {
        const auto at = item.find('@');
        OperatingCondition c;
        if (at == std::string::npos || !parse_real(item.substr(0, at), c.speed_rpm) ||
            !parse_real(item.substr(at + 1), c.load_Nm))
            throw std::invalid_argument("pmsm: conditions = " + value_excerpt(text) + ": " +
                                        quoted_excerpt(item) +
                                        " is not SPEED@LOAD (rpm@N m, e.g. 2500@2), nor 'paper'");
        if (!(c.speed_rpm > 0))
            throw std::invalid_argument("pmsm: conditions: speed " + quoted_excerpt(item) +
                                        " must be > 0 rpm");
        out.push_back(c);
    }
    return out;
}

PmsmSources simulate_sources(const SimulatorConfig& base, const std::vector<OperatingCondition>& conditions) {
    PmsmSources out;
    for (std::size_t i = 0; i < conditions.size(); ++i) {
        SimulatorConfig config = base;
        config.condition = conditions[i];
        if (i > 0)
            config.seed = mix64(base.seed ^ stable_hash("pmsm condition " + std::to_string(i)));
        out.datasets.push_back(simulate_dataset(config));
        out.names.push_back("simulated " + format_real(config.condition.speed_rpm) + " rpm, " +
                            format_real(config.condition.load_Nm) + " N m");
    }
    return out;
}

} // namespace mhb::pmsm
