#include "runner/plugins/plugin_loader.hpp"

#include <dlfcn.h>
#include <map>
#include <vector>

#include "problems/core/sha256.hpp"
#include "runner/plugin_api.hpp"
#include "runner/plugins/load_failure.hpp"

namespace mhb {
namespace {

// `key=value;` pairs in the order written.
std::vector<std::pair<std::string, std::string>> settings_of(const std::string& text) {
    std::vector<std::pair<std::string, std::string>> out;
    std::size_t start = 0;
    while (start < text.size()) {
        const auto end = std::min(text.find(';', start), text.size());
        const std::string item = text.substr(start, end - start);
        const auto eq = item.find('=');
        if (!item.empty())
            out.emplace_back(item.substr(0, eq), eq == std::string::npos ? "" : item.substr(eq + 1));
        start = end + 1;
    }
    return out;
}

// What the user rebuilds, and against what: the fix is always the same.
const char* const rebuild_hint =
    "rebuild the plug-in with the compiler and flags of this mhbench, against the "
    "package it installed (find_package(mhbench))";

// Stamps every entry with the module it came from (module_path, module_sha256).
template <class Product>
Registry<Product> stamped(const Registry<Product>& from, const std::string& path, const std::string& sha256) {
    Registry<Product> out(from.kind());
    for (auto entry : from.entries()) {
        entry.module_path = path;
        entry.module_sha256 = sha256;
        out.add(std::move(entry));
    }
    return out;
}

} // namespace

std::string build_settings_difference(const std::string& plugin, const std::string& host) {
    const auto theirs = settings_of(plugin);
    const auto ours = settings_of(host);
    const std::map<std::string, std::string> their_map(theirs.begin(), theirs.end());
    const std::map<std::string, std::string> our_map(ours.begin(), ours.end());
    const auto value = [](const std::map<std::string, std::string>& m, const std::string& key) {
        const auto found = m.find(key);
        return found == m.end() ? std::string("(unset)") : found->second;
    };
    // Our order first (the compiler before the layouts it causes), then keys only the plug-in has.
    std::vector<std::string> keys;
    for (const auto& [key, v] : ours)
        keys.push_back(key);
    for (const auto& [key, v] : theirs)
        if (our_map.count(key) == 0)
            keys.push_back(key);
    for (const auto& key : keys)
        if (value(their_map, key) != value(our_map, key))
            return key + '=' + value(their_map, key) + ", this mhbench has " + key + '=' +
                   value(our_map, key);
    return "";
}

LoadedPlugin load_plugin(const std::filesystem::path& given) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(given, ec))
        throw PluginError("plugin " + given.string() + ": " +
                          (std::filesystem::exists(given, ec) ? "is not a file" : "no such file"));
    LoadedPlugin plugin;
    plugin.path = std::filesystem::absolute(given).lexically_normal().string();
    // The hash of the bytes about to be loaded; sha256_file_hex names the file if it cannot be read.
    try {
        plugin.sha256 = sha256_file_hex(plugin.path);
    } catch (const std::runtime_error& e) {
        throw PluginError(std::string("plugin ") + e.what());
    }
    // RTLD_NOW: a symbol the module needs and mhbench does not export is an error here, with its
    // name, rather than a crash in the middle of a study. RTLD_LOCAL: two modules' own symbols
    // never resolve to each other. Never dlclose'd: its code is behind every factory it registered.
    void* handle = ::dlopen(plugin.path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        const char* why = ::dlerror();
        throw PluginError("plugin " + plugin.path + ": cannot be loaded" +
                          load_failure(why != nullptr ? why : "unknown"));
    }
    using EntryPoint = const PluginInfo* (*)();
    void* symbol = ::dlsym(handle, MHBENCH_PLUGIN_ENTRY_POINT);
    if (symbol == nullptr)
        throw PluginError("plugin " + plugin.path + ": is not an mhbench plug-in (no " +
                          MHBENCH_PLUGIN_ENTRY_POINT +
                          " entry point: end it with MHBENCH_PLUGIN(name, "
                          "register_function) and build it with mhbench_add_plugin)");
    const PluginInfo* info = reinterpret_cast<EntryPoint>(symbol)();
    if (info == nullptr)
        throw PluginError("plugin " + plugin.path + ": its entry point returned nothing");
    // The version first: the rest of PluginInfo means what this mhbench thinks only if it agrees.
    if (info->abi_version != plugin_abi_version)
        throw PluginError("plugin " + plugin.path + ": built for plug-in ABI " +
                          std::to_string(info->abi_version) + ", this mhbench has ABI " +
                          std::to_string(plugin_abi_version) + "; " + rebuild_hint);
    const std::string difference =
        build_settings_difference(info->build != nullptr ? info->build : "", plugin_build_settings());
    if (!difference.empty())
        throw PluginError("plugin " + plugin.path + ": built with " + difference + "; " + rebuild_hint);
    plugin.name = info->name != nullptr ? info->name : plugin.path;
    if (info->register_components == nullptr)
        throw PluginError("plugin " + plugin.path + ": has no registration function");
    AlgorithmRegistry algorithms("algorithm");
    ProblemRegistry problems("problem");
    try {
        info->register_components(algorithms, problems);
    } catch (const std::exception& e) {
        throw PluginError("plugin " + plugin.path + ": its registration failed: " + e.what());
    }
    plugin.algorithms = stamped(algorithms, plugin.path, plugin.sha256);
    plugin.problems = stamped(problems, plugin.path, plugin.sha256);
    return plugin;
}

} // namespace mhb
