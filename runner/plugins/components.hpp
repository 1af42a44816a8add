// The optimisers and problem families a command can name: the built-in ones plus those of the
// plug-in modules it was given (`--plugin`, `plugins =` in a study file). A plug-in may not reuse
// a name that is taken (built-in, or by an earlier plug-in): it is refused, naming both, rather
// than namespaced, so that specs, labels and run identities stay as users write them.
#pragma once

#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/problem_registry.hpp"
#include "runner/plugins/plugin_loader.hpp"

namespace mhb {

struct Components {
    AlgorithmRegistry algorithms{"algorithm"};
    ProblemRegistry problems{"problem"};
};

// The built-in registries plus each plug-in in order. Throws PluginError (runner/plugins/plugin_loader.hpp)
// with one line: a module that cannot be loaded, or a name it registers that is already taken.
Components compose_components(const std::vector<std::string>& plugin_paths);

} // namespace mhb
