# The plug-in contract's headers: the closure of runner/plugin_api.hpp's includes, nothing more
# (tests/plugin_example checks it by building against the installed copy). Named relative to the
# source tree, as `#include` names them. One list for everything that follows them: the install
# (cmake/MhbInstall.cmake), the symbols the executable exports to plug-ins
# (cmake/MhbPluginSymbols.cmake) and the contract's fingerprint, in mhbench's build and in every
# plug-in's (cmake/mhbenchContract.cmake, installed beside this file).
set(MHBENCH_CONTRACT_HEADERS
    algorithms/algorithm_registry.hpp
    algorithms/optimizer.hpp
    algorithms/sampling.hpp
    problems/core/parameters.hpp
    problems/core/registry.hpp
    problems/core/rng.hpp
    problems/core/spec.hpp
    problems/core/text_excerpt.hpp
    problems/objective.hpp
    problems/problem.hpp
    problems/problem_registry.hpp
    problems/trace_recorder.hpp
    runner/plugin_api.hpp)
