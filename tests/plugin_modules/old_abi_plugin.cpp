// A module whose entry point reports a plug-in ABI this mhbench does not have (as one built
// against another mhbench's headers would): mhbench must refuse it before reading anything else.
#include "runner/plugin_api.hpp"

extern "C" __attribute__((visibility("default"))) const mhb::PluginInfo* mhbench_plugin() {
    static const mhb::PluginInfo info{mhb::plugin_abi_version + 998, "old", "", nullptr};
    return &info;
}
