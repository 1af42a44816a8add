// The plug-in loader's checks (runner/plugins/plugin_loader.hpp): the build settings of a plug-in and of
// mhbench are compared setting by setting, naming the first that differs; a missing module is one
// line; an undefined symbol is named demangled. The refusals of real modules are in
// tests/integration/plugin_test.cpp, module hashes in run identities in run_identity_versions_test.cpp.
#include <gtest/gtest.h>
#include <string>

#include "runner/plugin_api.hpp"
#include "runner/plugins/load_failure.hpp"
#include "runner/plugins/plugin_loader.hpp"

namespace mhb {
namespace {

TEST(PluginBuildSettings, TheFirstDifferingSettingIsNamedWithBothValues) {
    const std::string host = plugin_build_settings();
    EXPECT_EQ(build_settings_difference(host, host), "");
    EXPECT_NE(host.find("eigen_max_align_bytes="), std::string::npos) << host;
    EXPECT_EQ(build_settings_difference("compiler=gcc-11;eigen=3.4.0;", "compiler=gcc-12;eigen=3.3.9;"),
              "compiler=gcc-11, this mhbench has compiler=gcc-12");
    EXPECT_EQ(build_settings_difference("compiler=gcc-12;", "compiler=gcc-12;cxx11_abi=1;"),
              "cxx11_abi=(unset), this mhbench has cxx11_abi=1");
    EXPECT_EQ(build_settings_difference("compiler=gcc-12;glibcxx_debug=1;", "compiler=gcc-12;"),
              "glibcxx_debug=1, this mhbench has glibcxx_debug=(unset)");
}

TEST(PluginLoader, AnUndefinedSymbolIsNamedDemangledWithWhatToDo) {
    EXPECT_EQ(load_failure("/x/mine.so: undefined symbol: _ZTVN3mhb3FooE"),
              ": undefined symbol vtable for mhb::Foo (a symbol mhbench does not export to plug-ins: build "
              "the plug-in against this mhbench's installed package, and call only what its headers "
              "declare)");
    // A versioned C symbol stays as it is; any other reason is given whole.
    EXPECT_EQ(load_failure("/x/mine.so: undefined symbol: frobnicate, version LIB_1").substr(0, 30),
              ": undefined symbol frobnicate ");
    EXPECT_EQ(load_failure("/x/mine.so: invalid ELF header"), " (/x/mine.so: invalid ELF header)");
}

TEST(PluginLoader, AMissingFileIsOneLineNamingIt) {
    try {
        (void)load_plugin("/nonexistent/mine.so");
        FAIL() << "loaded a missing file";
    } catch (const PluginError& e) {
        EXPECT_STREQ(e.what(), "plugin /nonexistent/mine.so: no such file");
    }
}

} // namespace
} // namespace mhb
