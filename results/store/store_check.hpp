// The files rendered from store.bin, checked against it, for a study that has lost the marker
// whose sizes and checksums vouch for them (deleted, or not copied: `cp DIR/* NEW/` skips
// dot-files). Internal to results/store: load_study calls it.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "results/store/study_data.hpp"

namespace mhb {

// Each file rendered from store.bin (runs.csv, curves.csv, ..., timings.csv) must be, byte for
// byte, what store.bin renders for the runs of `data` (as load_study read them from runs.csv,
// `run_lines` giving each one's line there): a run is found in store.bin by its algorithm,
// problem, budget, run index and seed, and any of the records stored under those (the newest of
// each identity, as the writer keeps them) may be the one rendered. Throws std::runtime_error, in
// one line naming the file and line of the first difference.
void check_rendered_files_against_store(const std::filesystem::path& dir, const StudyData& data,
                                        const std::vector<std::size_t>& run_lines);

} // namespace mhb
