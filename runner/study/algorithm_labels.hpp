// The labels tables and figures name algorithms by, when a spec gives no `label=`: a grid variant's
// (itlbo[T-S+O-]) and the short display name its registration declares (problems/core/registry.hpp
// DisplayName: "BOBYQA" for nlopt:algorithm=LN_BOBYQA), with the parameters set away from their
// defaults as a suffix ("PSO (w=0.7)"). A label is display only: no run's identity holds it
// (runner/execution/run_identity.cpp keys runs by canonical specs), so relabelling keeps a study
// resumable.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/spec.hpp"

namespace mhb {

// The readable name of one variant of a grid: the name with the braced values, booleans as a
// letter and a sign (itlbo[T+S-O+]), other values as key=value (pso[w=0.4]).
std::string grid_label(const AlgorithmRegistry::Entry& entry,
                       const std::vector<std::pair<std::string, std::string>>& varying);

// The short label of `spec` (validated; any `label=` removed): the entry's display name and its
// non-default parameters, "PSO (w=0.7)", "CMA-ES (BIPOP, lambda=20)"; the canonical spec for an
// entry that declares no display name (a plug-in's, `external`).
std::string short_label(const AlgorithmRegistry& registry, const Spec& spec);

// The labels of a study's specs without `label=`, decided together so that they are unique and do
// not depend on the order: a short label two specs would share, or that another spec's given or grid
// label already is, falls back to the canonical spec. `wanted`: canonical spec -> short label;
// `taken`: the labels given with `label=` and the grid labels. Returns canonical spec -> label.
std::map<std::string, std::string> unique_short_labels(const std::map<std::string, std::string>& wanted,
                                                       const std::vector<std::string>& taken);

} // namespace mhb
