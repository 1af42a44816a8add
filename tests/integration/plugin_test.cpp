// Plug-in modules (`--plugin`, runner/plugins/plugin_loader.hpp) by the CLI: study.ini, list and eval know
// the plug-in; and every refusal is one line and a non-zero exit: a missing file, a file that is
// not a module, a module without the entry point, another plug-in ABI, another Eigen alignment, a
// name already taken, a call mhbench does not export, and a plug-in rebuilt under a stored study. (The
// example plug-in built against the installed package: extension_example_test.cpp.)
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

#include "cli_harness.hpp"
#include "support/files.hpp"

namespace {

using mhb::test_support::read_text;
using mhb::testing_cli::lines_of;
using mhb::testing_cli::run_mhbench;
using mhb::testing_cli::run_shell;
using mhb::testing_cli::scratch_directory;
using mhb::testing_cli::shell_quoted;

const std::string test_plugins = MHB_TEST_PLUGIN_DIR;

// The extension example's study (tests/integration/extension_example_test.cpp), as options.
const std::string example_study_options =
    "--algorithms 'one-plus-one:step=0.5 tlbo:np=10' --problems 'booth sphere:dim=2' "
    "--runs 3 --evaluations 2000 --no-report --quiet";

// Checks that a command failed with exit code 1 and one line on stderr holding `expected`.
void expect_refused(const mhb::testing_cli::CliResult& r, const std::string& expected) {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(lines_of(r.err).size(), 1U) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
}

TEST(PluginCli, StudyIniRecordsThePluginSoThatTheStudyFileResumesIt) {
    const auto dir = scratch_directory() / "study-ini";
    std::filesystem::remove_all(dir);
    const std::string plugin = test_plugins + "/test_plugin_booth.so";
    auto r = run_mhbench("run --plugin " + shell_quoted(plugin) + " " + example_study_options + " --out " +
                         shell_quoted(dir));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(read_text(dir / "study.ini").find("plugins = " + plugin + "\n"), std::string::npos);
    // No --plugin: study.ini names it, and every run is found in the store.
    r = run_mhbench("run --study-file " + shell_quoted(dir / "study.ini") + " --out " + shell_quoted(dir) +
                    " --no-report");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("12 found in the store"), std::string::npos) << r.out;
    std::filesystem::remove_all(dir);
}

TEST(PluginCli, MergeLoadsThePluginsOfTheShardsStudyIni) {
    const auto dir = scratch_directory() / "merged";
    std::filesystem::remove_all(dir);
    const std::string plugin = test_plugins + "/test_plugin_booth.so";
    for (const char* shard : {"1", "2"}) {
        const auto r = run_mhbench("run --plugin " + shell_quoted(plugin) + " " + example_study_options +
                                   " --shard " + shard + "/2 --out " + shell_quoted(dir / shard));
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const auto r = run_mhbench("merge " + shell_quoted(dir / "all") + " " + shell_quoted(dir / "1") + " " +
                               shell_quoted(dir / "2") + " --no-report --quiet");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(lines_of(read_text(dir / "all" / "runs.csv")).size(), 13U); // the header and 12 runs
    std::filesystem::remove_all(dir);
}

TEST(PluginCli, ListAndEvalShowThePluginsComponents) {
    const std::string plugin = test_plugins + "/test_plugin_booth.so";
    auto r = run_mhbench("list algorithms --plugin " + shell_quoted(plugin));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("one-plus-one (version 1)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("plugin: " + plugin), std::string::npos) << r.out;
    r = run_mhbench("list problems --plugin " + shell_quoted(plugin));
    EXPECT_NE(r.out.find("booth (version 1)"), std::string::npos) << r.out;
    r = run_shell("printf '1 3\\n0 0\\n' | '" MHB_CLI_PATH "' eval --problem booth --points - --plugin " +
                  shell_quoted(plugin));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "0\n74\n");
}

TEST(PluginCli, PluginCheckPassesTheExamplesOptimizerAndProblem) {
    const std::string plugin = test_plugins + "/test_plugin_booth.so";
    const auto r = run_mhbench("plugin-check --plugin " + shell_quoted(plugin) +
                               " --algorithm one-plus-one --problem booth --evaluations 500 --runs 2");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    for (const char* line :
         {"pass  optimum      f(x*) = f* = 0", "pass  budget       every run made exactly 500",
          "pass  same seed", "pass  threads", "verdict: pass"})
        EXPECT_NE(r.out.find(line), std::string::npos) << line << '\n' << r.out;
    const auto quiet = run_mhbench("plugin-check --plugin " + shell_quoted(plugin) +
                                   " --algorithm one-plus-one --problem booth --evaluations 500 --runs 2 -q");
    ASSERT_EQ(quiet.exit_code, 0) << quiet.out << quiet.err;
    EXPECT_EQ(quiet.out, "verdict: pass\n"); // -q: the failed checks and the verdict only
}

TEST(PluginCli, EachUnusableModuleIsRefusedInOneLine) {
    const std::string study = " --algorithms tlbo --problems sphere:dim=2 --evaluations 100 --quiet --out " +
                              shell_quoted(scratch_directory() / "refused");
    const auto text = scratch_directory() / "not_a_module.so";
    { std::ofstream(text) << "not a shared object\n"; }
    // Each module, and the start of the one line it must get.
    const std::pair<std::string, std::string> cases[] = {
        {"/nonexistent/plugin.so", "plugin /nonexistent/plugin.so: no such file"},
        {text.string(), ": cannot be loaded ("},
        {test_plugins + "/test_plugin_no_entry.so",
         "is not an mhbench plug-in (no mhbench_plugin entry point"},
        {test_plugins + "/test_plugin_old_abi.so",
         "built for plug-in ABI 999, this mhbench has ABI 1; rebuild the plug-in"},
        {test_plugins + "/test_plugin_other_contract.so",
         "built with contract=0123456789abcdef, this mhbench has contract="},
        {test_plugins + "/test_plugin_misaligned.so",
         "built with eigen_max_align_bytes=64, this mhbench has eigen_max_align_bytes="},
        {test_plugins + "/test_plugin_clash.so",
         "problem 'sphere' is already built into mhbench; rename it in the plug-in"},
        {test_plugins + "/test_plugin_unexported.so",
         ": cannot be loaded: undefined symbol mhb::sha256_hex[abi:cxx11](std::basic_string_view<char, "
         "std::char_traits<char> >) (a symbol mhbench does not export to plug-ins: build the plug-in "
         "against this mhbench's installed package"},
    };
    for (const auto& [module, expected] : cases)
        expect_refused(run_mhbench("run --plugin " + shell_quoted(module) + study), expected);
    // Two modules that register the same names (a copy of one).
    const auto copy = scratch_directory() / "booth_copy.so";
    std::filesystem::copy_file(test_plugins + "/test_plugin_booth.so", copy,
                               std::filesystem::copy_options::overwrite_existing);
    expect_refused(run_mhbench("list --plugin " + shell_quoted(test_plugins + "/test_plugin_booth.so") +
                               " --plugin " + shell_quoted(copy)),
                   "algorithm 'one-plus-one' is already registered by plugin " + test_plugins);
    expect_refused(run_mhbench("eval --problem booth --points - --plugin /nonexistent/plugin.so"),
                   "no such file");
}

TEST(PluginCli, APluginRebuiltUnderAStoredStudyIsRefusedLikeAChangedDataFile) {
    const auto dir = scratch_directory() / "rebuilt";
    std::filesystem::remove_all(dir);
    const auto plugin = scratch_directory() / "rebuilt_booth.so";
    std::filesystem::copy_file(test_plugins + "/test_plugin_booth.so", plugin,
                               std::filesystem::copy_options::overwrite_existing);
    const std::string command =
        "run --plugin " + shell_quoted(plugin) + " " + example_study_options + " --out " + shell_quoted(dir);
    ASSERT_EQ(run_mhbench(command).exit_code, 0);
    // Other bytes, the same loadable module (as a rebuild with another compiler flag would be).
    { std::ofstream(plugin, std::ios::app | std::ios::binary) << "rebuilt"; }
    auto r = run_mhbench(command);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("algorithm 'one-plus-one': the plugin " + plugin.string() +
                         " changed since the study started (sha256 "),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("problem 'booth': the plugin"), std::string::npos) << r.err;
    // The built-in optimiser on a built-in problem is untouched: only the plug-in's runs change.
    EXPECT_NE(r.err.find("9 stored runs would change"), std::string::npos) << r.err;
    r = run_mhbench(command + " --recompute-changed");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::filesystem::remove_all(dir);
}

} // namespace
