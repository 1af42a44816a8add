// Implementation versions in run identities: version 1 leaves a run's identity as it was before
// versions existed (stored studies keep working), a bump changes it, and extending a study whose
// stored runs came from another version is refused naming the component and both versions,
// unless the runs are to be computed again. Likewise a plug-in module's SHA-256 (runner/plugins/
// plugin_loader.hpp): it joins the identity of its components' runs, built-in ones keep theirs.
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

#include "problems/core/sha256.hpp"
#include "results/store/run_key.hpp"
#include "results/store/study_writer.hpp"
#include "runner/execution/run_identity.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/study.hpp"
#include "tests/support/files.hpp"

namespace mhb {
namespace {

Study small_pso_study() {
    Study study;
    study.algorithms = {"pso"};
    study.problems = {"sphere:dim=2"};
    study.runs = 2;
    Budget budget;
    budget.max_evaluations = 200;
    study.budgets = {budget};
    return study;
}

// The built-in registry of `Product`s with entry `name` changed by `change`.
template <class Product, class Change>
Registry<Product> with_entry(const Registry<Product>& builtin, const std::string& name, Change change) {
    Registry<Product> registry(builtin.kind());
    for (auto entry : builtin.entries()) {
        if (entry.name == name)
            change(entry);
        registry.add(entry);
    }
    return registry;
}

// The built-in registry of `Product`s with entry `name` at `version`.
template <class Product>
Registry<Product> with_version(const Registry<Product>& builtin, const std::string& name, int version) {
    return with_entry(builtin, name, [version](auto& entry) { entry.version = version; });
}

// The built-in registry with entry `name` as if a plug-in module of hash `sha256` registered it.
template <class Product>
Registry<Product> from_module(const Registry<Product>& builtin, const std::string& name,
                              const std::string& sha256) {
    return with_entry(builtin, name, [&sha256](auto& entry) {
        entry.module_path = "/plugins/mine.so";
        entry.module_sha256 = sha256;
    });
}

// Writes every run of `study` into a study directory at `dir`.
void write_every_run_into(const std::filesystem::path& dir, const PreparedStudy& study) {
    StudyWriter writer(dir, "study", "", study.parameter_columns, false, study.algorithm_infos(),
                       study_run_keys(study));
    for (std::int64_t id = 0; id < study.run_count(); ++id)
        writer.append(execute_run(study.request(id)), 0.0);
    writer.finish();
}

// The message of the std::runtime_error StudyWriter throws for `study` in `dir`, or "".
std::string refusal(const std::filesystem::path& dir, const PreparedStudy& study) {
    try {
        StudyWriter writer(dir, "study", "", study.parameter_columns, false, study.algorithm_infos(),
                           study_run_keys(study));
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(RunIdentityVersions, VersionOneHashesTheFactsOfBeforeVersions) {
    const PreparedStudy study = prepare_study(small_pso_study());
    const RunKey key = run_key(study, 1);
    const RunRequest request = study.request(1);
    // The facts as they were written before implementation versions existed.
    const std::string before = "format = " + std::to_string(store_format_version) +
                               "\nalgorithm = pso\nproblem = sphere:dim=2\nbudget = evaluations=200\n"
                               "run = 1\nseed = " +
                               std::to_string(request.seed) + '\n';
    EXPECT_EQ(key.facts, before);
    EXPECT_EQ(key.identity, sha256_hex(before));
}

TEST(RunIdentityVersions, ABumpChangesTheIdentityAndNamesBothVersions) {
    const PreparedStudy v1 = prepare_study(small_pso_study());
    const PreparedStudy v2 = prepare_study(small_pso_study(), with_version(builtin_algorithms(), "pso", 2));
    const RunKey old_key = run_key(v1, 0);
    const RunKey new_key = run_key(v2, 0);
    EXPECT_NE(old_key.identity, new_key.identity);
    EXPECT_EQ(old_key.slot, new_key.slot);
    EXPECT_EQ(describe_run_change(old_key, new_key),
              "algorithm 'pso': the stored runs were made by version 1, this mhbench has version 2");
    const PreparedStudy p3 =
        prepare_study(small_pso_study(), builtin_algorithms(), with_version(builtin_problems(), "sphere", 3));
    EXPECT_EQ(describe_run_change(old_key, run_key(p3, 0)),
              "problem 'sphere': the stored runs were made by version 1, this mhbench has version 3");
    // The seed does not depend on the version: a bumped optimiser is compared on the same streams.
    EXPECT_EQ(v1.request(0).seed, v2.request(0).seed);
}

TEST(RunIdentityVersions, ExtendingRunsOfAnotherVersionIsRefusedUnlessRecomputed) {
    const auto dir = test_support::fresh_temporary_path("mhb_versions_", "extend");
    const PreparedStudy v1 = prepare_study(small_pso_study());
    write_every_run_into(dir, v1);

    Study larger = small_pso_study();
    larger.runs = 3;
    EXPECT_EQ(refusal(dir, prepare_study(larger)), ""); // same version: extends

    const PreparedStudy v2 = prepare_study(larger, with_version(builtin_algorithms(), "pso", 2));
    const std::string message = refusal(dir, v2);
    EXPECT_NE(message.find("2 stored runs would change:\n  algorithm 'pso': the stored runs were made by "
                           "version 1, this mhbench has version 2\npass --recompute-changed"),
              std::string::npos)
        << message;

    StudyRunKeys keys = study_run_keys(v2);
    keys.recompute_changed = true;
    const StudyWriter writer(dir, "study", "", v2.parameter_columns, false, v2.algorithm_infos(), keys);
    EXPECT_TRUE(writer.completed().empty()); // every run of version 1 is computed again
}

TEST(RunIdentityVersions, APluginModulesHashJoinsTheIdentityWhileBuiltInsKeepTheirs) {
    const Study study = small_pso_study();
    const RunKey built_in = run_key(prepare_study(study), 0);
    EXPECT_EQ(built_in.facts.find("module"), std::string::npos) << built_in.facts;
    const std::string one(64, 'a');
    const std::string two(64, 'b');
    const RunKey first = run_key(prepare_study(study, from_module(builtin_algorithms(), "pso", one)), 0);
    const RunKey again = run_key(prepare_study(study, from_module(builtin_algorithms(), "pso", one)), 0);
    const RunKey rebuilt = run_key(prepare_study(study, from_module(builtin_algorithms(), "pso", two)), 0);
    EXPECT_NE(first.identity, built_in.identity);
    EXPECT_EQ(first.identity, again.identity);
    EXPECT_NE(first.identity, rebuilt.identity);
    EXPECT_EQ(first.slot, rebuilt.slot);
    EXPECT_EQ(
        describe_run_change(first, rebuilt),
        "algorithm 'pso': the plugin /plugins/mine.so changed since the study started (sha256 aaaaaaaa.. -> "
        "bbbbbbbb..)");
    EXPECT_EQ(describe_run_change(built_in, first),
              "algorithm 'pso': the stored runs were made by mhbench's built-in algorithm, it now comes from "
              "plugin /plugins/mine.so");
    const RunKey problem = run_key(
        prepare_study(study, builtin_algorithms(), from_module(builtin_problems(), "sphere", one)), 0);
    EXPECT_EQ(describe_run_change(problem, built_in), "problem 'sphere': the stored runs were made by plugin "
                                                      "/plugins/mine.so, it is now built into mhbench");
}

} // namespace
} // namespace mhb
