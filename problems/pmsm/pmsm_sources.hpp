// Where a `pmsm` problem's data come from: one or more dataset files (`data=a.csv+b.csv`), or the
// drive simulator at one or more operating conditions (`speed=`/`load=`, or
// `conditions=2500@2+2000@2`, or `conditions=paper` for the paper's three). Several datasets are
// fitted jointly with one parameter vector by every model.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "problems/pmsm/dataset.hpp"
#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/drive_simulator.hpp"
#include "problems/problem.hpp"

namespace mhb::pmsm {

struct PmsmSources {
    std::vector<Dataset> datasets;
    std::vector<std::string> names; // a file's path, or "simulated 2500 rpm, 2 N m"
    std::vector<DataFile> files;    // the files read, with their SHA-256 (empty when simulated)

    // The true or nominal (Rs, Ld, Lq, psi) of the first dataset whose metadata give all four.
    [[nodiscard]] std::optional<Eigen::Vector4d> nominal_parameters() const;
};

// Reads `paths` joined by '+' (each at most once).
PmsmSources read_sources(const std::string& joined_paths, const DatasetReadOptions& options);

// `SPEED@LOAD` conditions joined by '+' (rpm @ N m), or "paper" for 2500@2+2500@3+2000@2.
// Throws std::invalid_argument naming the bad item.
std::vector<OperatingCondition> parse_conditions(const std::string& text);

// Simulates `base` at each condition. The first condition uses base.seed; condition i > 0 a seed
// derived from it and i, so that the noise of two conditions is independent.
PmsmSources simulate_sources(const SimulatorConfig& base, const std::vector<OperatingCondition>& conditions);

} // namespace mhb::pmsm
