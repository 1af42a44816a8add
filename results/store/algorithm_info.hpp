// An algorithm of a study as its report names it: one row of algorithms.csv.
#pragma once

#include <string>

namespace mhb {

// An algorithm of the study as the report shows it (algorithms.csv).
struct AlgorithmInfo {
    std::string spec;      // canonical: defaults dropped, values normalised, as in RunRecord::algorithm
    std::string label;     // display name: `label=` of the spec, a grid label such as itlbo[T-S+O-], or spec
    std::string full_spec; // every declared parameter with its value, e.g. tlbo:np=50,r=coordinate
};

} // namespace mhb
