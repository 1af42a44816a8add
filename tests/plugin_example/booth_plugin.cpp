// The example plug-in: the components of booth_components.hpp as a module that `mhbench run
// --plugin booth_plugin.so` loads. This line is all a plug-in adds to in-tree code.
#include "booth_components.hpp"
#include "runner/plugin_api.hpp"

MHBENCH_PLUGIN("booth", booth_example::register_components)
