// The example plug-in as if built against another mhbench's contract headers (a copy installed
// from another commit, even of the same version): only the contract's fingerprint differs, and
// mhbench must refuse it, since a header change may move a virtual function that no size shows.
#undef MHB_PLUGIN_CONTRACT
#define MHB_PLUGIN_CONTRACT "0123456789abcdef"
#include "../plugin_example/booth_components.hpp"
#include "runner/plugin_api.hpp"

MHBENCH_PLUGIN("booth", booth_example::register_components)
