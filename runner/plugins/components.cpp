#include "runner/plugins/components.hpp"

#include <algorithm>
#include <filesystem>

#include "runner/plugins/plugin_loader.hpp"

namespace mhb {
namespace {

// Adds the plug-in's entries, refusing a name already registered, with where it came from.
template <class Product>
void merge(Registry<Product>& into, const Registry<Product>& from, const std::string& path) {
    for (const auto& entry : from.entries()) {
        if (into.contains(entry.name)) {
            const auto& taken = into.find(entry.name);
            throw PluginError("plugin " + path + ": " + into.kind() + " '" + entry.name + "' is already " +
                              (taken.module_path.empty() ? std::string("built into mhbench")
                                                         : "registered by plugin " + taken.module_path) +
                              "; rename it in the plug-in");
        }
        into.add(entry);
    }
}

} // namespace

Components compose_components(const std::vector<std::string>& plugin_paths) {
    Components c{builtin_algorithms(), builtin_problems()};
    std::vector<std::string> loaded;
    for (const auto& path : plugin_paths) {
        // The same file named twice (on the command line and in the study file) is one plug-in.
        const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
        if (std::find(loaded.begin(), loaded.end(), absolute) != loaded.end())
            continue;
        loaded.push_back(absolute);
        const LoadedPlugin plugin = load_plugin(path);
        merge(c.algorithms, plugin.algorithms, plugin.path);
        merge(c.problems, plugin.problems, plugin.path);
    }
    return c;
}

} // namespace mhb
