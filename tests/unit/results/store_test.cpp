// The study store: records round-trip exactly, files are sorted by run id whatever the order
// runs finish in, an interrupted study resumes, and damaged directories give clear errors.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "results/store/algorithm_info.hpp"
#include "results/store/csv.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_writer.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

fs::path fresh_store_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("mhb_store_test_" + name);
    fs::remove_all(dir);
    return dir;
}

RunRecord make_pmsm_record(std::int64_t id) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = "pso:c1=2,w=0.5";
    r.problem = "pmsm:load=2,speed=2500";
    r.run_index = id;
    r.seed = 0xfedcba9876543210ULL + static_cast<std::uint64_t>(id);
    r.best_f = 0.1 + static_cast<double>(id) / 3.0;
    r.f_opt = 0.1;
    r.evaluations = 100 + id;
    r.iterations = 3;
    r.best_x = {0.33, 0.00324 + 1e-7 * static_cast<double>(id), 0.00324, 0.0776};
    r.parameter_names = {"Rs", "Ld", "Lq", "psi"};
    r.true_parameters = {0.33, 0.00324, 0.00324, 0.0776};
    r.x_opt = {0.331, 0.003241, 0.003239, 0.07761};
    for (std::int64_t i = 0; i <= 3; ++i)
        r.curve.push_back({i, 50 * (i + 1), 1.0 / static_cast<double>(i + 1), r.best_x});
    r.checkpoints = {{1, 9.0}, {2, 5.0}, {100 + id, r.best_f}};
    return r;
}

TEST(Store, KeepsEachRunsBudgetAndTheStudysAlgorithms) {
    const fs::path dir = fresh_store_dir("budgets");
    const std::vector<AlgorithmInfo> algorithms = {
        {"itlbo:obl=off", "itlbo[O-]", "itlbo:np=50,obl=off,p=0.1"},
        {"tlbo", "TLBO, \"plain\"", "tlbo:np=50"}};
    {
        StudyWriter w(dir, "s\n", "", {}, false, algorithms);
        RunRecord a = make_pmsm_record(0);
        a.budget = "iterations=150";
        RunRecord b = make_pmsm_record(1);
        b.budget = "evaluations=15050,target=1e-08";
        w.append(b, 0.0);
        w.append(a, 0.0);
        w.finish();
    }
    const StudyData data = load_study(dir);
    ASSERT_EQ(data.runs.size(), 2u);
    EXPECT_EQ(data.runs[0].budget, "iterations=150");
    EXPECT_EQ(data.runs[1].budget, "evaluations=15050,target=1e-08");
    ASSERT_EQ(data.algorithms.size(), 2u);
    for (std::size_t i = 0; i < algorithms.size(); ++i) {
        EXPECT_EQ(data.algorithms[i].spec, algorithms[i].spec);
        EXPECT_EQ(data.algorithms[i].label, algorithms[i].label);
        EXPECT_EQ(data.algorithms[i].full_spec, algorithms[i].full_spec);
    }
    // A study written again without algorithm information leaves no stale algorithms.csv behind.
    StudyWriter again(dir, "s\n", "", {}, true);
    EXPECT_FALSE(fs::exists(dir / StudyFiles::algorithms));
}

TEST(Store, RoundTripsRecordsExactlyAndSortsByRunId) {
    const fs::path dir = fresh_store_dir("roundtrip");
    {
        StudyWriter w(dir, "[study]\nseed=1\n", "threads=2\n", {"Rs", "Ld", "Lq", "psi"}, false);
        for (std::int64_t id : {2, 0, 1}) // finishing out of order, as parallel runs do
            w.append(make_pmsm_record(id), 0.5);
        RunRecord failed;
        failed.run_id = 3;
        failed.algorithm = "tlbo";
        failed.problem = "sphere:dim=2";
        failed.ok = false;
        failed.message = "boom, with a \"quote\"\nand a newline";
        w.append(failed, 0.0);
        w.finish();
    }
    EXPECT_TRUE(fs::exists(dir / "store.bin")); // kept: a finished study can grow
    const StudyData data = load_study(dir);
    ASSERT_EQ(data.runs.size(), 4u);
    EXPECT_EQ(data.parameter_columns, (std::vector<std::string>{"Rs", "Ld", "Lq", "psi"}));
    for (std::int64_t id = 0; id < 3; ++id) {
        const RunRecord expected = make_pmsm_record(id);
        const RunRecord& got = data.runs[static_cast<std::size_t>(id)];
        EXPECT_EQ(got.run_id, id);
        EXPECT_EQ(got.algorithm, expected.algorithm);
        EXPECT_EQ(got.seed, expected.seed);
        EXPECT_EQ(got.best_f, expected.best_f); // exact, not approximate
        EXPECT_EQ(got.best_x, expected.best_x);
        EXPECT_EQ(got.parameter_names, expected.parameter_names);
        EXPECT_EQ(got.true_parameters, expected.true_parameters);
        EXPECT_EQ(got.x_opt, expected.x_opt);
        ASSERT_EQ(got.curve.size(), 4u);
        EXPECT_EQ(got.curve[2].best_f, 1.0 / 3.0);
        EXPECT_EQ(got.curve[2].best_x, expected.best_x);
        ASSERT_EQ(got.checkpoints.size(), 3u);
        EXPECT_EQ(got.checkpoints[2].evaluations, 100 + id);
    }
    EXPECT_FALSE(data.runs[3].ok);
    EXPECT_EQ(data.runs[3].message, "boom, with a \"quote\" and a newline");
    EXPECT_EQ(data.study_text, "[study]\nseed=1\n");
}

TEST(Store, ResumesAnInterruptedStudyKeepingFinishedRunsOnly) {
    const fs::path dir = fresh_store_dir("resume");
    {
        StudyWriter w(dir, "study A\n", "", {}, false);
        w.append(make_pmsm_record(0), 0.1);
        w.append(make_pmsm_record(1), 0.1);
        // No finish(): the process is "killed" here. Simulate a half-written third block.
        // A char array, not a C string: the zeros of the length are written too.
        const char half_block[] = "MHBRUN3\n\x40\0\0\0\0\0\0\0abc";
        std::ofstream(dir / "store.bin", std::ios::binary | std::ios::app)
            .write(half_block, sizeof half_block - 1);
    }
    EXPECT_FALSE(fs::exists(dir / "runs.csv"));
    EXPECT_THROW(load_study(dir), std::runtime_error); // unfinished: not a study to report on
    const auto stored = fs::file_size(dir / "store.bin");
    // Without run keys, runs belong to their study text: another study shares none of them.
    EXPECT_TRUE(StudyWriter(dir, "study B\n", "", {}, false).completed().empty());
    EXPECT_LT(fs::file_size(dir / "store.bin"), stored); // the half-written block is cut off
    {
        StudyWriter w(dir, "study A\n", "", {}, false);
        EXPECT_EQ(w.completed(), (std::set<std::int64_t>{0, 1}));
        w.append(make_pmsm_record(2), 0.1);
        w.finish();
    }
    EXPECT_EQ(load_study(dir).runs.size(), 3u);
    const std::string runs = read_whole_file(dir / "runs.csv");
    {
        // Finished: the same study again re-renders the same files from the store.
        StudyWriter w(dir, "study A\n", "", {}, false);
        EXPECT_EQ(w.completed(), (std::set<std::int64_t>{0, 1, 2}));
        w.finish();
        EXPECT_EQ(read_whole_file(dir / "runs.csv"), runs);
    }
    EXPECT_TRUE(StudyWriter(dir, "study A\n", "", {}, true).completed().empty()); // overwrite: a fresh store
}

TEST(Store, AHalfWrittenBlockBetweenCompleteOnesLosesOnlyItsRun) {
    // Threads write blocks concurrently at reserved positions, so a killed process may leave a
    // half-written block before complete ones: those are kept.
    const fs::path dir = fresh_store_dir("hole");
    std::uintmax_t first_end = 0;
    std::uintmax_t second_end = 0;
    {
        StudyWriter w(dir, "study A\n", "", {}, false);
        w.append(make_pmsm_record(0), 0.1);
        first_end = fs::file_size(dir / "store.bin");
        w.append(make_pmsm_record(1), 0.1);
        second_end = fs::file_size(dir / "store.bin");
        w.append(make_pmsm_record(2), 0.1);
    }
    {
        // Zeros over the second half of run 1's block, end mark included, as an unfinished write
        // leaves it: its framing is torn (a flipped byte inside a whole block is store_integrity_test's).
        std::fstream f(dir / "store.bin", std::ios::binary | std::ios::in | std::ios::out);
        const std::uintmax_t middle = first_end + (second_end - first_end) / 2;
        f.seekp(static_cast<std::streamoff>(middle));
        const std::string zeros(second_end - middle, '\0');
        f.write(zeros.data(), static_cast<std::streamsize>(zeros.size()));
    }
    StudyWriter w(dir, "study A\n", "", {}, false);
    EXPECT_EQ(w.completed(), (std::set<std::int64_t>{0, 2}));
    w.append(make_pmsm_record(1), 0.1);
    w.finish();
    ASSERT_EQ(load_study(dir).runs.size(), 3u);
    EXPECT_EQ(load_study(dir).runs[1].best_f, make_pmsm_record(1).best_f);
}

TEST(Store, DamagedDirectoriesGiveErrorsNamingTheFile) {
    const fs::path dir = fresh_store_dir("damaged");
    {
        StudyWriter w(dir, "s\n", "", {}, false);
        w.append(make_pmsm_record(0), 0.1);
        w.finish();
    }
    // Truncate curves.csv in the middle of a line.
    const fs::path curves = dir / "curves.csv";
    std::string text;
    {
        std::ifstream in(curves);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::ofstream(curves, std::ios::trunc) << text.substr(0, text.size() - 4);
    try {
        (void)load_study(dir);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("curves.csv"), std::string::npos) << e.what();
    }
    fs::remove(dir / "timings.csv");
    EXPECT_THROW(load_study(dir), std::runtime_error);
    EXPECT_THROW(load_study(dir / "nope"), std::runtime_error);
}

// Found by tests/fuzz/fuzz_study_dir: evals_to_target was read as a double and cast, so 1e300 or nan
// was undefined behaviour (a garbage count, or a UBSan report) rather than an error naming the cell.
TEST(Store, EvaluationsToTargetIsReadAsAnInteger) {
    const fs::path dir = fresh_store_dir("evals_to_target");
    {
        StudyWriter w(dir, "s\n", "", {}, false);
        RunRecord r = make_pmsm_record(0);
        r.evaluations_to_target = 1234;
        w.append(r, 0.1);
        w.finish();
    }
    ASSERT_EQ(load_study(dir).runs.at(0).evaluations_to_target, std::int64_t{1234});
    const fs::path runs = dir / StudyFiles::runs;
    std::string text;
    {
        std::ifstream in(runs);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    for (const std::string bad : {"1e300", "nan", "12.5"}) {
        const auto at = text.find(",1234,");
        ASSERT_NE(at, std::string::npos);
        std::string damaged = text;
        damaged.replace(at + 1, 4, bad);
        std::ofstream(runs, std::ios::trunc) << damaged;
        try {
            (void)load_study(dir);
            ADD_FAILURE() << bad << " was read";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("evals_to_target"), std::string::npos) << e.what();
        }
    }
}

TEST(Store, UnwritableOutputIsAClearError) {
    try {
        StudyWriter w("/proc/mhbench_cannot_write_here", "s\n", "", {}, false);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/proc/mhbench_cannot_write_here"), std::string::npos);
    }
}

// A writer killed before its study's marker was whole leaves the lock file and the marker's
// temporary file: the same command must take the directory up again, and any other file still
// makes it "not a mhbench study".
TEST(Store, ADirectoryKilledBeforeItsMarkerWasWholeIsTakenUpAgain) {
    const fs::path dir = fresh_store_dir("killed_before_marker");
    fs::create_directories(dir);
    std::ofstream(dir / StudyFiles::lock) << "command = mhbench run\n";
    std::ofstream(dir / (std::string(StudyFiles::marker) + ".tmp")) << "mhbench stu";
    EXPECT_NO_THROW(StudyWriter(dir, "s\n", "", {}, false));
    EXPECT_TRUE(fs::exists(dir / StudyFiles::marker));

    const fs::path other = fresh_store_dir("killed_before_marker_other");
    fs::create_directories(other);
    std::ofstream(other / StudyFiles::lock) << "command = mhbench run\n";
    std::ofstream(other / "notes.txt") << "mine";
    EXPECT_THROW(StudyWriter(other, "s\n", "", {}, false), std::runtime_error);
}

TEST(Csv, QuotesAndSplitsAndNumbersRoundTrip) {
    EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
    EXPECT_EQ(csv_split("1,\"a,\"\"b\"\"\",,x"), (std::vector<std::string>{"1", "a,\"b\"", "", "x"}));
    EXPECT_EQ(csv_number(0.1), "0.1");
    EXPECT_EQ(csv_number(1.0 / 3.0), "0.3333333333333333");
    EXPECT_THROW(csv_split("\"open"), std::runtime_error);
}

} // namespace
} // namespace mhb
