// Example: extending mhbench with your own problem and your own optimiser, then running them in a
// study beside the built-in ones. The problem, the optimiser and their registration (steps 1 to 3)
// are in tests/plugin_example/booth_components.hpp, shared with the plug-in module built from the
// same code (tests/plugin_example/); this file and that header are the whole of what a user
// writes. It is built and run as a test so that it keeps working, and so is the plug-in: built
// outside the tree against the installed package, run by `mhbench run --plugin`, it must give the
// records of the same code compiled in, byte for byte.
#include <filesystem>
#include <gtest/gtest.h>
#include <unistd.h>

#include "algorithms/algorithm_registry.hpp"
#include "cli_harness.hpp"
#include "plugin_example/booth_components.hpp"
#include "problems/problem_registry.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"

namespace {

// 3. Registration: the built-in components plus one entry each.
struct ExampleComponents {
    mhb::AlgorithmRegistry algorithms{"algorithm"};
    mhb::ProblemRegistry problems{"problem"};
    ExampleComponents() {
        mhb::register_builtin_algorithms(algorithms);
        mhb::register_builtin_problems(problems);
        booth_example::register_components(algorithms, problems);
    }
};

// 4. A study, as `mhbench run` would make it, written into `dir`.
mhb::Study example_study() {
    mhb::Study study;
    study.algorithms = {"one-plus-one:step=0.5", "tlbo:np=10"};
    study.problems = {"booth", "sphere:dim=2"};
    study.runs = 3;
    study.budgets.front().max_evaluations = 2000;
    return study;
}

// The same study as `mhbench run` options (the plug-in test below).
const char* const example_options =
    "--algorithms 'one-plus-one:step=0.5 tlbo:np=10' --problems 'booth sphere:dim=2' "
    "--runs 3 --evaluations 2000 --no-report --quiet";

void run_example_study(const ExampleComponents& components, const std::filesystem::path& dir) {
    const mhb::PreparedStudy prepared =
        mhb::prepare_study(example_study(), components.algorithms, components.problems);
    std::filesystem::remove_all(dir);
    mhb::StudyWriter writer(dir, mhb::study_ini(prepared.study), "", prepared.parameter_columns, false);
    EXPECT_EQ(mhb::run_study(prepared, writer).kept, 12);
}

TEST(ExtensionExample, OwnProblemAndOptimiserRunInAStudyBesideBuiltInOnes) {
    const ExampleComponents components;
    const auto dir = std::filesystem::temp_directory_path() / ("mhb_extension_" + std::to_string(::getpid()));
    run_example_study(components, dir);

    for (const auto& r : mhb::load_study(dir).runs) {
        EXPECT_TRUE(r.ok) << r.message;
        EXPECT_EQ(r.evaluations, 2000);
        // A fixed step of 0.5 stalls at an error of order 1e-3; TLBO goes much further.
        EXPECT_LT(*r.error(), r.algorithm.rfind("tlbo", 0) == 0 ? 1e-10 : 1e-2)
            << r.algorithm << " on " << r.problem;
    }
    mhb::Study zero_step = example_study(); // a step of 0 is refused by the declared range
    zero_step.algorithms = {"one-plus-one:step=0"};
    EXPECT_THROW((void)mhb::prepare_study(zero_step, components.algorithms, components.problems),
                 std::invalid_argument);
    std::filesystem::remove_all(dir);
}

using mhb::test_support::read_text;
using mhb::testing_cli::run_mhbench;
using mhb::testing_cli::run_shell;
using mhb::testing_cli::scratch_directory;
using mhb::testing_cli::shell_quoted;

TEST(PluginPackage, ExampleBuiltAgainstTheInstalledPackageGivesTheRecordsOfTheInTreeExample) {
    const auto scratch = scratch_directory() / "package";
    std::filesystem::remove_all(scratch);
    const auto prefix = scratch / "prefix";
    const auto build = scratch / "build";
    const std::string cmake = shell_quoted(MHB_CMAKE_COMMAND);
    auto r =
        run_shell(cmake + " --install " + shell_quoted(MHB_BINARY_DIR) + " --prefix " + shell_quoted(prefix));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    // The contract's headers and what they include, nothing more (cmake/MhbInstall.cmake).
    std::size_t headers = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(prefix / "include" / "mhbench"))
        headers += entry.is_regular_file() ? 1U : 0U;
    EXPECT_EQ(headers, 13U);
    EXPECT_TRUE(
        std::filesystem::exists(prefix / "lib" / "cmake" / "mhbench" / "mhbenchConfigVersion.cmake") ||
        std::filesystem::exists(prefix / "lib64" / "cmake" / "mhbench" / "mhbenchConfigVersion.cmake"));
    // Configured and built outside the source tree, by find_package(mhbench 0.1) alone.
    const auto source = scratch / "booth";
    std::filesystem::create_directories(source);
    for (const char* file : {"CMakeLists.txt", "booth_plugin.cpp", "booth_components.hpp"})
        std::filesystem::copy_file(std::filesystem::path(MHB_SOURCE_DIR) / "tests" / "plugin_example" / file,
                                   source / file);
    r = run_shell(cmake + " -S " + shell_quoted(source) + " -B " + shell_quoted(build) + " -G " +
                  shell_quoted(MHB_CMAKE_GENERATOR) + " -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=" +
                  shell_quoted(MHB_CXX_COMPILER) + " -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    r = run_shell(cmake + " --build " + shell_quoted(build));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;

    const auto plugged = scratch / "plugged";
    r = run_mhbench("run --plugin " + shell_quoted(build / "booth_plugin.so") + " " + example_options +
                    " --out " + shell_quoted(plugged));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto built_in = scratch / "built-in";
    run_example_study(ExampleComponents(), built_in);
    // Byte for byte: the same seeds, evaluations, best f and x, and the same convergence.
    for (const char* file : {"runs.csv", "curves.csv", "improvements.csv"}) {
        const std::string expected = read_text(built_in / file);
        EXPECT_FALSE(expected.empty()) << file;
        EXPECT_EQ(read_text(plugged / file), expected) << file;
    }
    std::filesystem::remove_all(scratch);
}

} // namespace
