// A flux map: currents i_d, i_q (A) and the flux linkages psi_d, psi_q (V s) measured at them, one
// entry per point. Read from a user's CSV (columns i_d,i_q,psi_d,psi_q in any order) or taken
// from the Baldor map shipped in the executable (problems/fluxmap/data/, see its README).
//
// The reader checks everything and throws std::runtime_error with one line naming the file, the
// line and the column of the first defect, e.g. `map.csv: line 7, column 'psi_q': 'nan' is not
// finite (NaN or infinity)`.
#pragma once

#include <Eigen/Core>
#include <iosfwd>
#include <string>

namespace mhb::fluxmap {

// Physical ranges of a point. A machine's currents are far inside 1e5 A and its flux linkages far
// inside 100 V s; a file beyond them is damaged or in wrong units (mA, mV s), and squares of the
// model's currents stay far from overflow.
inline constexpr double max_current = 1e5; // A
inline constexpr double max_flux = 100.0;  // V s

struct FluxMap {
    Eigen::ArrayXd i_d, i_q, psi_d, psi_q;

    [[nodiscard]] Eigen::Index size() const { return i_d.size(); }
};

// `min_points`: fewer points than the model's parameters cannot determine them.
FluxMap read_flux_map_csv(std::istream& in, const std::string& source, Eigen::Index min_points);
// Reads the file once; `sha256` (when given) receives the SHA-256 of exactly the bytes parsed.
FluxMap read_flux_map_csv(const std::string& path, Eigen::Index min_points, std::string* sha256 = nullptr);

// The shipped map of the Baldor ECS101M0H7EF4 at 400 rpm (567 points), parsed once per process.
const FluxMap& baldor_flux_map();
// Its name as shown in messages and its SHA-256, as recorded in data/README.md.
inline constexpr const char* baldor_map_name = "baldor-ecs101m0h7ef4-400rpm.csv";
inline constexpr const char* baldor_map_sha256 =
    "222207ef2c7bc4d901ff13115ab284942115fccbbb9ed33fa4571d41256c3aa0";

} // namespace mhb::fluxmap
