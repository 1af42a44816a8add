// The random draws that define a BBOB instance, exactly as COCO defines them (the legacy
// BBOB 2009 generator that COCO keeps so that every instance is the same as in 2009):
//   - a Park-Miller "minimal standard" generator with a 32-entry shuffle table (bbob2009_unif),
//   - Box-Muller normals from it (bbob2009_gauss),
//   - rotations by modified Gram-Schmidt on a Gaussian matrix (bbob2009_compute_rotation),
//   - x_opt on a 1e-4 grid in [-4, 4] and f_opt in [-1000, 1000] rounded to 0.01.
// Instance i of function f is drawn from rseed = f + 10000 i (f4 uses 3 and f18 uses 17, the
// functions they derive from). Read from COCO's code-experiments/src/suite_bbob_legacy_code.c and
// suite_bbob.c; written anew here.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace mhb::bbob {

// n uniform numbers in (0, 1) from `seed` (|seed|, at least 1).
std::vector<double> legacy_uniform(std::size_t n, std::int64_t seed);
// n standard normals from `seed`: sqrt(-2 log u_i) cos(2 pi u_{n+i}) over 2n uniforms.
std::vector<double> legacy_gauss(std::size_t n, std::int64_t seed);
// A D x D orthogonal matrix from `seed` (columns orthonormalised in order).
Eigen::MatrixXd legacy_rotation(std::int64_t seed, Eigen::Index dimension);
// The optimum's position: 8 floor(1e4 u) / 1e4 - 4 per coordinate (0 becomes -1e-5).
Eigen::VectorXd legacy_xopt(std::int64_t seed, Eigen::Index dimension);
// The optimal value of function `function` (1-24) in instance `instance`.
double legacy_fopt(int function, std::int64_t instance);

// The seed COCO derives for function `function`, instance `instance` (f4 -> 3, f18 -> 17).
std::int64_t instance_seed(int function, std::int64_t instance);

} // namespace mhb::bbob
