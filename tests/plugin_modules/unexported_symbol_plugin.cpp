// A plug-in that calls a function of mhbench outside the contract (problems/core/sha256.hpp is not
// an installed header, and the executable does not export it): dlopen refuses it, and mhbench must
// name the symbol demangled, with what to do about it, rather than the loader's mangled name.
#include "problems/core/sha256.hpp"
#include "runner/plugin_api.hpp"

namespace {

void register_nothing(mhb::AlgorithmRegistry& /*algorithms*/, mhb::ProblemRegistry& /*problems*/) {
    (void)mhb::sha256_hex("not exported");
}

} // namespace

MHBENCH_PLUGIN("unexported", register_nothing)
