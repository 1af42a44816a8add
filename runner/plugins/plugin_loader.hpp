// Loads a plug-in module (runner/plugin_api.hpp) into mhbench: dlopen, the one C entry point, the
// check of its ABI version and build settings against mhbench's own, then its registration into
// registries of its own. Every refusal is one line naming the file and what to do about it, as a
// PluginError; the CLI prints it and exits non-zero.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "algorithms/algorithm_registry.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {

struct PluginError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A module that was loaded and registered: its components, each entry's module_path and
// module_sha256 set to the file's. The module stays loaded for the life of the process (its code
// is behind every factory and every object it made).
struct LoadedPlugin {
    std::string path;   // absolute
    std::string sha256; // of the file's content when it was loaded
    std::string name;   // what the plug-in calls itself
    AlgorithmRegistry algorithms{"algorithm"};
    ProblemRegistry problems{"problem"};
};

// Throws PluginError: the file is missing or not a loadable module (with dlopen's reason), has no
// entry point, was built for another plug-in ABI or with other build settings, or its
// registration threw.
LoadedPlugin load_plugin(const std::filesystem::path& path);

// The first setting (`key=value;...`, runner/plugin_api.hpp) on which two builds differ, worded
// "eigen_max_align_bytes=64, this mhbench has eigen_max_align_bytes=16"; empty when they agree.
std::string build_settings_difference(const std::string& plugin, const std::string& host);

} // namespace mhb
