// Job arrays: `mhbench run --shard i/n` runs a deterministic, cost-balanced share of a study and
// `mhbench merge` joins the shards into the directory one process writes, records byte for byte;
// the merge refuses shards of different studies, duplicates, missing and unfinished shards.
#include <filesystem>
#include <fstream>

#include "cli_harness.hpp"
#include "problems/core/sha256.hpp"
#include "runner/distribution/shards.hpp"
#include "runner/study/study.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;

const std::string study_options =
    "--algorithms 'itlbo:obl={on,off} tlbo cmaes' --problems 'pmsm sphere:dim={3,8}' "
    "--budget iterations=5 --budget evaluations=400 --runs 3 --quiet ";

fs::path fresh_shards_dir(const std::string& name) {
    const fs::path dir = mhb::testing_cli::scratch_directory() / ("shards_" + name);
    fs::remove_all(dir);
    return dir;
}

TEST(Shards, ThreeShardsMergedAreTheStudyOneProcessWritesByteForByte) {
    const fs::path one = fresh_shards_dir("one");
    ASSERT_EQ(run_mhbench("run " + study_options + "--no-report --threads 2 --out " + one.string()).exit_code,
              0);
    std::vector<fs::path> shards;
    for (int i = 1; i <= 3; ++i) {
        shards.push_back(fresh_shards_dir("part" + std::to_string(i)));
        const auto r = run_mhbench("run " + study_options + "--threads 1 --shard " + std::to_string(i) +
                                   "/3 --out " + shards.back().string());
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(read_text(shards.back() / "shard.txt"), "shard = " + std::to_string(i) + "/3\n");
        EXPECT_FALSE(fs::exists(shards.back() / "report")); // a shard is part of a study
    }
    const fs::path merged = fresh_shards_dir("merged");
    // Any order of the shard directories.
    const auto r = run_mhbench("merge " + merged.string() + " " + shards[2].string() + " " +
                               shards[0].string() + " " + shards[1].string() + " --no-figures --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* file : {"runs.csv", "curves.csv", "checkpoints.csv", "trajectories.csv",
                             "improvements.csv", "study.ini", "algorithms.csv"})
        EXPECT_EQ(read_text(merged / file), read_text(one / file)) << file;
    EXPECT_TRUE(fs::exists(merged / "report"));
    EXPECT_NE(read_text(merged / "context.ini").find("shards = 3\n"), std::string::npos);
}

TEST(Shards, TheSplitIsDeterministicCompleteAndBalancedByCost) {
    mhb::Study s;
    s.algorithms = {"itlbo", "pso"}; // ITLBO spends about (D + 1) times PSO's evaluations per iteration
    s.problems = {"sphere:dim={2,20}"};
    s.runs = 10;
    s.budgets = {mhb::parse_budget("iterations=20")};
    const mhb::PreparedStudy p = mhb::prepare_study(s);
    const auto shards = mhb::shard_run_ids(p, 4);
    EXPECT_EQ(shards, mhb::shard_run_ids(p, 4)); // the same on every machine
    std::vector<std::int64_t> all;
    for (const auto& shard : shards)
        all.insert(all.end(), shard.begin(), shard.end());
    std::sort(all.begin(), all.end());
    ASSERT_EQ(all.size(), 40u);
    for (std::int64_t i = 0; i < 40; ++i)
        EXPECT_EQ(all[static_cast<std::size_t>(i)], i);
    // Balanced by cost, not by count: the expensive ITLBO runs at D = 20 are spread out.
    const auto cost = mhb::estimated_run_costs(p);
    double largest = 0;
    std::vector<double> totals;
    for (const auto& shard : shards) {
        double total = 0;
        for (const auto id : shard) {
            total += cost[static_cast<std::size_t>(id)];
            largest = std::max(largest, cost[static_cast<std::size_t>(id)]);
        }
        totals.push_back(total);
    }
    EXPECT_LE(*std::max_element(totals.begin(), totals.end()) -
                  *std::min_element(totals.begin(), totals.end()),
              largest);
    EXPECT_EQ(mhb::shard_run_ids(p, 50).size(), 50u); // more shards than runs: some are empty
    EXPECT_THROW((void)mhb::parse_shard("0/3"), std::invalid_argument);
    EXPECT_THROW((void)mhb::parse_shard("4/3"), std::invalid_argument);
    EXPECT_THROW((void)mhb::parse_shard("1-3"), std::invalid_argument);
}

// Shards 1/2 and 2/2 of the study, in directories `name`1 and `name`2; fewer when one failed.
std::vector<fs::path> shards_of_two(const std::string& name) {
    std::vector<fs::path> shards;
    for (int i = 1; i <= 2; ++i) {
        const fs::path dir = fresh_shards_dir(name + std::to_string(i));
        const auto r =
            run_mhbench("run " + study_options + "--shard " + std::to_string(i) + "/2 --out " + dir.string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        if (r.exit_code == 0)
            shards.push_back(dir);
    }
    return shards;
}

TEST(Shards, MergeRefusesOtherStudiesDuplicatesMissingAndUnfinishedShards) {
    const std::vector<fs::path> shards = shards_of_two("pair");
    ASSERT_EQ(shards.size(), 2u);
    const fs::path other = fresh_shards_dir("other");
    ASSERT_EQ(run_mhbench("run " + study_options + "--seed 2 --shard 2/2 --out " + other.string()).exit_code,
              0);
    const fs::path whole = fresh_shards_dir("whole");
    ASSERT_EQ(run_mhbench("run " + study_options + "--no-report --out " + whole.string()).exit_code, 0);
    const auto merge = [&](const std::string& dirs) {
        return run_mhbench("merge " + fresh_shards_dir("out").string() + " " + dirs);
    };
    const std::string a = shards[0].string();
    const std::string b = shards[1].string();
    EXPECT_EQ(merge(a + " " + other.string()).err, "mhbench merge: " + other.string() +
                                                       ": holds another study than " + a +
                                                       " (their study.ini differ)\n");
    EXPECT_EQ(merge(a + " " + a + " " + b).err,
              "mhbench merge: shard 1/2 is given twice: " + a + " and " + a + "\n");
    EXPECT_EQ(merge(b).err, "mhbench merge: shard 1/2 is missing\n");
    EXPECT_EQ(merge(a + " " + whole.string()).err, "mhbench merge: " + whole.string() +
                                                       ": is not a shard (no shard.txt); mhbench merge joins "
                                                       "the directories of mhbench run --shard i/n\n");
    EXPECT_EQ(merge(a).exit_code, 1);
    EXPECT_FALSE(fs::exists(fresh_shards_dir("out") / "runs.csv"));
    // An unfinished shard (its runs.csv gone, its store left) is named as such.
    fs::remove(shards[1] / "runs.csv");
    const auto unfinished = merge(a + " " + b);
    EXPECT_EQ(unfinished.exit_code, 1);
    EXPECT_NE(unfinished.err.find(b + ": holds an unfinished study"), std::string::npos) << unfinished.err;
    // Resuming a shard directory as another shard (or as the whole study) is refused.
    const auto wrong = run_mhbench("run " + study_options + "--shard 1/2 --out " + b);
    EXPECT_EQ(wrong.exit_code, 1);
    EXPECT_EQ(wrong.err, "mhbench run: " + b +
                             ": holds the runs of shard 2/2, not of shard 1/2; choose "
                             "another --out or pass --overwrite\n");
}

} // namespace

namespace {

// Issue 34: `mhbench merge S1 S1 S2` would leave S1 the whole study with a shard.txt of 1/2, and
// a merge into a finished study would replace it unasked. OUT that is one of the shards (as a file,
// not as text) is always refused, OUT that holds a study unless --overwrite, each in one line
// with nothing touched; --overwrite replaces OUT's study with the merged one.
TEST(Shards, MergeRefusesAnOutThatIsOneOfItsShardsOrHoldsAStudyUnlessOverwrite) {
    const std::vector<fs::path> shards = shards_of_two("own");
    ASSERT_EQ(shards.size(), 2u);
    const std::string a = shards[0].string();
    const std::string b = shards[1].string();
    const std::string a_runs = read_text(shards[0] / "runs.csv");
    const auto into_a = run_mhbench("merge " + a + " " + a + " " + b + " --no-report");
    EXPECT_EQ(into_a.exit_code, 2);
    EXPECT_EQ(into_a.err, "mhbench merge: OUT " + a + " is one of the shard directories to merge (" + a +
                              "); give another OUT\n");
    const std::string b_as_written = (shards[1].parent_path() / "." / shards[1].filename()).string();
    const auto into_b = run_mhbench("merge " + b_as_written + " " + a + " " + b + " --no-report --overwrite");
    EXPECT_EQ(into_b.exit_code, 2);
    EXPECT_EQ(into_b.err, "mhbench merge: OUT " + b_as_written +
                              " is one of the shard directories to merge (" + b + "); give another OUT\n");
    EXPECT_EQ(read_text(shards[0] / "runs.csv"), a_runs);
    EXPECT_EQ(read_text(shards[0] / "shard.txt"), "shard = 1/2\n");

    // A finished study of its own, and a copy of a shard: refused, then replaced with --overwrite.
    const fs::path other = fresh_shards_dir("own_other");
    ASSERT_EQ(run_mhbench("run " + study_options + "--seed 2 --no-report --out " + other.string()).exit_code,
              0);
    const std::string other_runs = read_text(other / "runs.csv");
    const auto into_other = run_mhbench("merge " + other.string() + " " + a + " " + b + " --no-report");
    EXPECT_EQ(into_other.exit_code, 1);
    EXPECT_EQ(into_other.err, "mhbench merge: OUT " + other.string() +
                                  " holds a study (.mhbench-study); pass --overwrite to replace it, or give "
                                  "another OUT\n");
    EXPECT_EQ(read_text(other / "runs.csv"), other_runs);
    const fs::path merged = fresh_shards_dir("own_merged");
    ASSERT_EQ(run_mhbench("merge " + merged.string() + " " + a + " " + b + " --no-report").exit_code, 0);
    const auto replaced =
        run_mhbench("merge " + other.string() + " " + a + " " + b + " --no-report --overwrite");
    ASSERT_EQ(replaced.exit_code, 0) << replaced.err;
    for (const char* file : {"runs.csv", "curves.csv", "study.ini", "algorithms.csv", ".mhbench-study"})
        EXPECT_EQ(read_text(other / file), read_text(merged / file)) << file;
    const fs::path copy = fresh_shards_dir("own_copy");
    fs::copy(shards[0], copy);
    ASSERT_EQ(
        run_mhbench("merge " + copy.string() + " " + a + " " + b + " --no-report --overwrite").exit_code, 0);
    EXPECT_EQ(read_text(copy / "runs.csv"), read_text(merged / "runs.csv"));
    EXPECT_FALSE(fs::exists(copy / "shard.txt")) << "the merged study is whole";
}

// The case: shard 1/2 on drive.csv, the file regenerated, shard 2/2, merge. study.ini names
// the same path for both; the hashes the shards recorded tell them apart.
TEST(Shards, MergeRefusesShardsThatReadDifferentDataOrWereBuiltDifferently) {
    const fs::path data = fresh_shards_dir("drive.csv");
    ASSERT_EQ(run_mhbench("simulate --out " + data.string()).exit_code, 0);
    const std::string old_hash = mhb::sha256_hex(read_text(data));
    const std::string study = "--algorithms pso --problems pmsm:data=" + data.string() +
                              " --iterations 3 --runs 2 --quiet --no-report --out ";
    const fs::path s1 = fresh_shards_dir("data1");
    const fs::path s2 = fresh_shards_dir("data2");
    ASSERT_EQ(run_mhbench("run " + study + s1.string() + " --shard 1/2").exit_code, 0);
    ASSERT_EQ(run_mhbench("simulate --load 3 --out " + data.string()).exit_code, 0);
    const std::string new_hash = mhb::sha256_hex(read_text(data));
    ASSERT_EQ(run_mhbench("run " + study + s2.string() + " --shard 2/2").exit_code, 0);
    const fs::path merged = fresh_shards_dir("data_merged");
    const auto mixed = run_mhbench("merge " + merged.string() + " " + s1.string() + " " + s2.string());
    EXPECT_EQ(mixed.exit_code, 1);
    EXPECT_EQ(mixed.err, "mhbench merge: " + fs::absolute(data).lexically_normal().string() + ": sha256 " +
                             new_hash + " in " + s2.string() + ", sha256 " + old_hash + " in " + s1.string() +
                             "\nmhbench merge: the shards of a study must read the same data with the same "
                             "build; run the differing shards again\n");
    EXPECT_FALSE(fs::exists(merged));

    // Shard 1/2 again on today's file: the shards agree, but the build recorded differs.
    ASSERT_EQ(run_mhbench("run " + study + s1.string() + " --shard 1/2 --overwrite").exit_code, 0);
    std::string context = read_text(s1 / "context.ini");
    const auto commit = context.find("git_commit = ");
    context.replace(commit, context.find('\n', commit) - commit, "git_commit = 0123abcd");
    std::ofstream(s1 / "context.ini", std::ios::trunc) << context;
    const auto other_build = run_mhbench("merge " + merged.string() + " " + s1.string() + " " + s2.string());
    EXPECT_EQ(other_build.exit_code, 1);
    EXPECT_NE(other_build.err.find("mhbench merge: " + s2.string() + ": was computed by mhbench "),
              std::string::npos)
        << other_build.err;
    EXPECT_NE(other_build.err.find(", " + s1.string() + " by mhbench "), std::string::npos)
        << other_build.err;
    EXPECT_NE(other_build.err.find(" commit 0123abcd"), std::string::npos) << other_build.err;

    // The same build and data on both: merged.
    ASSERT_EQ(run_mhbench("run " + study + s1.string() + " --shard 1/2 --overwrite").exit_code, 0);
    const auto joined =
        run_mhbench("merge " + merged.string() + " " + s1.string() + " " + s2.string() + " --no-report");
    EXPECT_EQ(joined.exit_code, 0) << joined.err;
}

TEST(Shards, TheSlurmExampleRunsEveryTaskAndMerges) {
    const fs::path dir = fresh_shards_dir("slurm");
    fs::create_directories(dir);
    std::ofstream(dir / "study.ini") << "algorithms = tlbo pso\nproblems = sphere:dim=3\nruns = 5\nbudget = "
                                        "iterations=5\n";
    const std::string script = std::string(MHB_SOURCE_DIR) + "/scripts/slurm-array.sh";
    const std::string env = "MHBENCH='" + std::string(MHB_CLI_PATH) + "' SLURM_ARRAY_TASK_COUNT=2 ";
    for (int i = 1; i <= 2; ++i) {
        const auto r = mhb::testing_cli::run_shell("cd '" + dir.string() + "' && " + env +
                                                   "SLURM_ARRAY_TASK_ID=" + std::to_string(i) + " bash '" +
                                                   script + "' study.ini out");
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const auto merged =
        mhb::testing_cli::run_shell("cd '" + dir.string() + "' && MHBENCH='" + std::string(MHB_CLI_PATH) +
                                    "' bash '" + script + "' --merge 2 out");
    ASSERT_EQ(merged.exit_code, 0) << merged.err;
    EXPECT_TRUE(fs::exists(dir / "out" / "runs.csv"));
    EXPECT_NE(merged.out.find("merged 2 shards (10 runs)"), std::string::npos) << merged.out;
}

} // namespace
