// The plug-in contract: what a shared module loaded by `mhbench run --plugin lib.so` provides. A
// plug-in is C++ compiled against mhbench's installed headers (find_package(mhbench), then
// mhbench_add_plugin); it adds optimisers and problem families to the registries, exactly as an
// in-tree file does (algorithms/README.md), and ends with one line:
//
//   MHBENCH_PLUGIN("booth", register_booth)   // void register_booth(AlgorithmRegistry&, ProblemRegistry&)
//
// The one C entry point (mhbench_plugin) hands mhbench a PluginInfo before any C++ object crosses
// the boundary: its first field is the plug-in ABI version and its build settings are plain text,
// so that mhbench can refuse a module built by another compiler, standard library or Eigen
// configuration (whose std::string, std::function or Eigen::VectorXd would differ in layout from
// its own) before it calls anything that passes one. The symbols the plug-in calls (Objective,
// Rng, parameters) are resolved from the mhbench executable at dlopen time.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "algorithms/algorithm_registry.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {

// Bumped whenever PluginInfo or the meaning of its fields changes.
inline constexpr std::uint32_t plugin_abi_version = 1;

// What the entry point returns. Layout fixed for a given plugin_abi_version.
struct PluginInfo {
    std::uint32_t abi_version; // plugin_abi_version of the headers the plug-in was built with
    const char* name;          // the plug-in's own name, for messages
    const char* build;         // plugin_build_settings() of the plug-in's build
    void (*register_components)(AlgorithmRegistry& algorithms, ProblemRegistry& problems);
};

namespace detail {
inline std::string setting(const char* key, const std::string& value) {
    return std::string(key) + '=' + value + ';';
}
} // namespace detail

// `key=value;...`: everything that must agree between mhbench and a plug-in for the objects they
// share to have one layout and one meaning. Inline, so that each side computes it with its own
// compiler and flags; mhbench compares the two texts (runner/plugins/plugin_loader.hpp).
inline std::string plugin_build_settings() {
    using detail::setting;
    std::string s;
#if defined(__clang__)
    s += setting("compiler", "clang-" + std::to_string(__clang_major__));
#elif defined(__GNUC__)
    s += setting("compiler", "gcc-" + std::to_string(__GNUC__));
#else
    s += setting("compiler", "unknown");
#endif
    s += setting("cplusplus", std::to_string(__cplusplus));
#if defined(_GLIBCXX_RELEASE)
    s += setting("libstdc++", std::to_string(_GLIBCXX_RELEASE));
    s += setting("cxx11_abi", std::to_string(_GLIBCXX_USE_CXX11_ABI));
#elif defined(_LIBCPP_VERSION)
    s += setting("libc++", std::to_string(_LIBCPP_VERSION));
#endif
#if defined(_GLIBCXX_DEBUG)
    s += setting("glibcxx_debug", "1"); // debug-mode containers have another layout
#endif
    s += setting("eigen", std::to_string(EIGEN_WORLD_VERSION) + '.' + std::to_string(EIGEN_MAJOR_VERSION) +
                              '.' + std::to_string(EIGEN_MINOR_VERSION));
    s += setting("eigen_max_align_bytes", std::to_string(EIGEN_MAX_ALIGN_BYTES));
    s += setting("eigen_max_static_align_bytes", std::to_string(EIGEN_MAX_STATIC_ALIGN_BYTES));
    s += setting("eigen_index_bytes", std::to_string(sizeof(Eigen::Index)));
    // The contract's headers themselves, fingerprinted at each side's build from the files its
    // compiler resolves (mhbench_add_plugin, cmake/mhbenchContract.cmake): another mhbench's, or a
    // changed copy, differ here. "none" in a build that did not go through mhbench's CMake.
#if defined(MHB_PLUGIN_CONTRACT)
    s += setting("contract", MHB_PLUGIN_CONTRACT);
#else
    s += setting("contract", "none");
#endif
    // A cheap fingerprint of the contract's own layout: headers of another mhbench differ here.
    s += setting("layout", std::to_string(sizeof(Objective)) + '/' + std::to_string(sizeof(Box)) + '/' +
                               std::to_string(sizeof(ParameterInfo)) + '/' +
                               std::to_string(sizeof(AlgorithmRegistry::Entry)) + '/' +
                               std::to_string(sizeof(ProblemRegistry::Entry)));
    return s;
}

} // namespace mhb

// The entry point's name, as mhbench looks it up with dlsym.
#define MHBENCH_PLUGIN_ENTRY_POINT "mhbench_plugin"

// Defines the entry point. NAME: a string literal; REGISTER: a function
// void(mhb::AlgorithmRegistry&, mhb::ProblemRegistry&) that adds the plug-in's components. The one
// symbol a plug-in exports (mhbench_add_plugin hides the rest).
#define MHBENCH_PLUGIN(NAME, REGISTER)                                                                       \
    extern "C" __attribute__((visibility("default"))) const mhb::PluginInfo* mhbench_plugin() {              \
        static const std::string build = mhb::plugin_build_settings();                                       \
        static const mhb::PluginInfo info{mhb::plugin_abi_version, NAME, build.c_str(), &(REGISTER)};        \
        return &info;                                                                                        \
    }
