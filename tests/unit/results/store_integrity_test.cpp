// What makes a study directory trustworthy beyond a kill -9: checksummed records (a damaged one is
// computed again, with a warning, never trusted), stores of the former block format still read,
// syncs at a bounded interval (a crash of the machine loses only the runs since the last one),
// finish() rendering exactly the study's runs, load_study refusing runs.csv of another study.ini,
// and no temporary file left by an error.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <span>

#include "results/store/csv.hpp"
#include "results/store/record_codec.hpp"
#include "results/store/run_key.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

fs::path fresh_store_integrity_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("mhb_store_integrity_" + name);
    fs::remove_all(dir);
    return dir;
}

RunRecord make_pso_sphere_record(std::int64_t id) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = "pso";
    r.problem = "sphere:dim=2";
    r.budget = "evaluations=100";
    r.run_index = id;
    r.seed = 1000 + static_cast<std::uint64_t>(id);
    r.best_f = 0.25 + static_cast<double>(id) / 7.0;
    r.evaluations = 100;
    r.iterations = 2;
    r.best_x = {0.5, -0.25 * static_cast<double>(id)};
    r.curve = {{0, 50, 4.0, {}}, {1, 100, r.best_f, {}}};
    r.checkpoints = {{50, 4.0}, {100, r.best_f}};
    r.improvements = ImprovementTrace{{{1, 4.0}, {60, r.best_f}}, r.best_f};
    return r;
}

constexpr const char* study_text = "[study]\nruns = 8\n";

// Keys as the runner makes them, for a study of `count` runs of pso on sphere:dim=2.
StudyRunKeys keys(std::int64_t count, std::optional<std::vector<std::int64_t>> run_ids = {}) {
    StudyRunKeys k;
    k.count = count;
    k.key = [](std::int64_t id) {
        RunKey key;
        key.identity = "identity of run " + std::to_string(id);
        key.slot = "pso | sphere:dim=2 | evaluations=100 | " + std::to_string(id);
        key.facts = "run = " + std::to_string(id) + "\n";
        key.algorithm = "pso";
        key.problem = "sphere:dim=2";
        return key;
    };
    k.run_ids = std::move(run_ids);
    return k;
}

StudyWriter open_study(const fs::path& dir, std::int64_t count = 8) {
    return StudyWriter(dir, study_text, "", {}, false, {}, keys(count));
}

const char* const rendered_files[] = {"runs.csv",         "curves.csv",       "checkpoints.csv",
                                      "trajectories.csv", "improvements.csv", "timings.csv",
                                      "study.ini",        ".mhbench-study"};

void expect_same_files(const fs::path& a, const fs::path& b) {
    for (const char* file : rendered_files)
        EXPECT_EQ(read_whole_file(a / file), read_whole_file(b / file)) << file;
}

// A study of `count` runs written in one go: what every damaged or crashed one must end up as.
// Named after the test: CTest runs the tests of this file in parallel processes.
fs::path clean_study(std::int64_t count = 8) {
    const fs::path dir = fresh_store_integrity_dir(
        std::string("clean_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    StudyWriter w = open_study(dir, count);
    for (std::int64_t id = 0; id < count; ++id)
        w.append(make_pso_sphere_record(id), 0.5);
    w.finish();
    return dir;
}

std::string bytes_of(const fs::path& path) {
    return read_whole_file(path);
}

void write_bytes(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

bool has_temporary_files(const fs::path& dir) {
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".tmp")
            return true;
    return false;
}

TEST(StoreIntegrity, AFlippedByteInARecordValueIsComputedAgainWithOneWarning) {
    const fs::path reference = clean_study(3);
    const fs::path dir = fresh_store_integrity_dir("flipped");
    std::uintmax_t first_end = 0;
    {
        StudyWriter w = open_study(dir, 3);
        w.append(make_pso_sphere_record(0), 0.5);
        first_end = fs::file_size(dir / "store.bin");
        w.append(make_pso_sphere_record(1), 0.5);
        w.append(make_pso_sphere_record(2), 0.5);
    }
    // One byte of run 1's best_f, inside its record body (the framing stays whole).
    std::string store = bytes_of(dir / "store.bin");
    ByteWriter value;
    value.f64(make_pso_sphere_record(1).best_f);
    const auto at = store.find(value.bytes(), first_end);
    ASSERT_NE(at, std::string::npos);
    store[at] = static_cast<char>(store[at] ^ 0x01);
    write_bytes(dir / "store.bin", store);
    {
        StudyWriter w = open_study(dir, 3);
        ASSERT_EQ(w.warnings().size(), 1u);
        EXPECT_EQ(w.warnings()[0], (dir / "store.bin").string() +
                                       ": the record of run 1 (pso, sphere:dim=2, evaluations=100, run 1) "
                                       "is damaged; it will be computed again");
        EXPECT_EQ(w.completed(), (std::set<std::int64_t>{0, 2}));
        w.append(make_pso_sphere_record(1), 0.5);
        w.finish();
    }
    expect_same_files(dir, reference);
    // Computed again: its good record is found from now on, and nothing more is said.
    StudyWriter again = open_study(dir, 3);
    EXPECT_TRUE(again.warnings().empty());
    EXPECT_EQ(again.completed().size(), 3u);
}

// The blocks of a store, with each payload changed by `change` (the size follows).
std::string rewrite_blocks(const std::string& store,
                           const std::function<std::string(std::size_t block, std::string payload)>& change) {
    std::string out;
    std::size_t position = 0;
    for (std::size_t block = 0; position < store.size(); ++block) {
        ByteReader header(std::string_view(store).substr(position + 8, 8), "size");
        const std::uint64_t size = header.u64();
        const std::string payload = change(block, store.substr(position + 16, size));
        ByteWriter new_size;
        new_size.u64(payload.size());
        out += store.substr(position, 8) + new_size.bytes() + payload + store.substr(position + 16 + size, 8);
        position += 16 + size + 8;
    }
    return out;
}

TEST(StoreIntegrity, StoresOfTheFormerBlockFormatStillLoad) {
    const fs::path reference = clean_study(3);
    const fs::path dir = fresh_store_integrity_dir("format3");
    fs::copy(reference, dir);
    // Format 3: the same blocks without the checksum trailer (tag and CRC, 16 bytes).
    const std::string checksummed = bytes_of(dir / "store.bin");
    write_bytes(dir / "store.bin", rewrite_blocks(checksummed, [](std::size_t, const std::string& payload) {
                    EXPECT_EQ(payload.substr(payload.size() - 16, 8), "MHBCRC4\n");
                    return payload.substr(0, payload.size() - 16);
                }));
    ASSERT_LT(fs::file_size(dir / "store.bin"), checksummed.size());
    fs::remove(dir / "runs.csv");
    {
        StudyWriter w = open_study(dir, 3);
        EXPECT_TRUE(w.warnings().empty());
        EXPECT_EQ(w.completed().size(), 3u);
        w.finish();
    }
    expect_same_files(dir, reference);
    // A format-3 record cut short inside (its framing whole) does not decode: computed again.
    write_bytes(dir / "store.bin",
                rewrite_blocks(bytes_of(dir / "store.bin"), [](std::size_t block, const std::string& p) {
                    return block == 2 ? p.substr(0, p.size() - 40) : p;
                }));
    StudyWriter w = open_study(dir, 3);
    ASSERT_EQ(w.warnings().size(), 1u);
    EXPECT_NE(w.warnings()[0].find("run 2 (pso, sphere:dim=2, evaluations=100, run 2) is damaged"),
              std::string::npos)
        << w.warnings()[0];
    EXPECT_EQ(w.completed(), (std::set<std::int64_t>{0, 1}));
}

TEST(StoreIntegrity, ACrashLosesOnlyTheRunsStoredSinceTheLastSync) {
    const fs::path reference = clean_study(8);
    const fs::path dir = fresh_store_integrity_dir("crash");
    std::uint64_t synced = 0;
    {
        StudyWriter w = open_study(dir);
        w.set_sync_policy({3, 1e9}); // every 3 runs; the clock never
        w.append(make_pso_sphere_record(0), 0.5);
        w.append(make_pso_sphere_record(1), 0.5);
        EXPECT_EQ(w.synced_bytes(), 0u);
        w.append(make_pso_sphere_record(2), 0.5);
        EXPECT_EQ(w.synced_bytes(), fs::file_size(dir / "store.bin"));
        for (std::int64_t id = 3; id < 8; ++id)
            w.append(make_pso_sphere_record(id), 0.5);
        synced = w.synced_bytes(); // after run 5
        ASSERT_LT(synced, fs::file_size(dir / "store.bin"));
    }
    const std::string store = bytes_of(dir / "store.bin");
    // What the disk may hold after a power cut: the unsynced tail gone, or its pages unwritten
    // (zeros) while the file's size was already on disk.
    const std::string dropped = store.substr(0, synced);
    const std::string zeroed = dropped + std::string(store.size() - synced, '\0');
    for (const std::string& after_crash : {dropped, zeroed}) {
        const fs::path crashed = fresh_store_integrity_dir("crashed_" + std::to_string(after_crash.size()));
        fs::copy(dir, crashed);
        write_bytes(crashed / "store.bin", after_crash);
        StudyWriter w = open_study(crashed);
        EXPECT_TRUE(w.warnings().empty());
        EXPECT_EQ(w.completed(), (std::set<std::int64_t>{0, 1, 2, 3, 4, 5}));
        w.append(make_pso_sphere_record(6), 0.5);
        w.append(make_pso_sphere_record(7), 0.5);
        w.finish();
        expect_same_files(crashed, reference);
    }
}

TEST(StoreIntegrity, FinishRendersExactlyTheRunsOfTheStudy) {
    const fs::path dir = fresh_store_integrity_dir("missing");
    StudyWriter w = open_study(dir, 3);
    w.append(make_pso_sphere_record(0), 0.5);
    w.append(make_pso_sphere_record(2), 0.5);
    try {
        w.finish();
        FAIL() << "a study without run 1 was rendered";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "holds no record of run 1 (pso, sphere:dim=2, evaluations=100, run 1)"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(dir / "runs.csv"));
    EXPECT_FALSE(has_temporary_files(dir));
    // A shard's directory holds its runs only: those are the ones it renders.
    StudyWriter shard(dir, study_text, "", {}, false, {}, keys(3, std::vector<std::int64_t>{2, 0}));
    shard.finish();
    EXPECT_EQ(load_study(dir).runs.size(), 2u);
    // A larger study's runs in the store are not this smaller study's.
    StudyWriter smaller = open_study(dir, 1);
    smaller.finish();
    EXPECT_EQ(load_study(dir).runs.size(), 1u);
}

TEST(StoreIntegrity, FinishRefusesAStudyIniReplacedWhileTheStudyRan) {
    const fs::path dir = fresh_store_integrity_dir("replaced");
    StudyWriter w = open_study(dir, 1);
    w.append(make_pso_sphere_record(0), 0.5);
    write_file_atomically(dir / "study.ini", "[study]\nruns = 99\n"); // another process's study
    try {
        w.finish();
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("study.ini: was replaced"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir / "runs.csv"));
}

TEST(StoreIntegrity, LoadStudyRefusesRunsRenderedForAnotherStudyIni) {
    const fs::path dir = fresh_store_integrity_dir("mixed");
    fs::copy(clean_study(3), dir);
    ASSERT_EQ(load_study(dir).runs.size(), 3u);
    const std::string study = read_whole_file(dir / "study.ini");
    write_bytes(dir / "study.ini", "[study]\nruns = 40\n");
    try {
        (void)load_study(dir);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("runs.csv: was rendered for another study.ini"),
                  std::string::npos)
            << e.what();
    }
    write_bytes(dir / "study.ini", study);
    const std::string runs = read_whole_file(dir / "runs.csv");
    write_bytes(dir / "runs.csv", runs.substr(0, runs.rfind('\n', runs.size() - 2) + 1)); // the last run gone
    // The marker's size and checksum of runs.csv see it first; a marker from before those were
    // written still has the number of runs.
    const std::string marker = read_whole_file(dir / ".mhbench-study");
    EXPECT_THROW((void)load_study(dir), std::runtime_error);
    write_bytes(dir / ".mhbench-study", marker.substr(0, marker.find("curves.csv = ")));
    try {
        (void)load_study(dir);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(
            std::string(e.what()).find("runs.csv: has 2 rows, but the study it was rendered for has 3 runs"),
            std::string::npos)
            << e.what();
    }
}

// The rendered files are not synced (the store is): after a crash of the machine one may be
// short, zeros or the previous study's, and load_study must refuse it, not read it, until the
// same command renders it again from the store.
TEST(StoreIntegrity, ARenderedFileTheDiskLostIsRefusedAndRenderedAgain) {
    const fs::path reference = clean_study(3);
    const std::string marker = read_whole_file(reference / ".mhbench-study");
    for (const char* name : std::span(rendered_files).first(6)) { // the CSV files
        const std::string facts = std::to_string(fs::file_size(reference / name)) + " bytes, crc32c ";
        EXPECT_NE(marker.find(std::string(name) + " = " + facts), std::string::npos) << marker;
        const std::string bytes = bytes_of(reference / name);
        for (const std::string& after_crash :
             {std::string(), bytes.substr(0, bytes.size() / 2), std::string(bytes.size(), '\0')}) {
            const fs::path dir =
                fresh_store_integrity_dir("lost_" + std::string(name) + std::to_string(after_crash.size()));
            fs::copy(reference, dir);
            write_bytes(dir / name, after_crash);
            try {
                (void)load_study(dir);
                FAIL() << name << " damaged was read";
            } catch (const std::runtime_error& e) {
                EXPECT_NE(std::string(e.what()).find(std::string(name) + ": is not the file the study wrote"),
                          std::string::npos)
                    << e.what();
                EXPECT_NE(std::string(e.what()).find("run the study's command again"), std::string::npos);
            }
            open_study(dir, 3).finish(); // the same command: every run is in the store
            expect_same_files(dir, reference);
        }
    }
}

// Issue 34: without its marker (deleted, or not copied by `cp DIR/* NEW/`), a study's rendered
// files are read only when they are what store.bin renders; finishing it again restores the
// marker. Without store.bin too (a study of format 2) they are read as they are.
TEST(StoreIntegrity, WithoutItsMarkerTheRenderedFilesAreCheckedAgainstTheStore) {
    const fs::path reference = clean_study(3);
    const fs::path dir = fresh_store_integrity_dir("unmarked");
    fs::copy(reference, dir);
    fs::remove(dir / ".mhbench-study");
    const StudyData intact = load_study(dir);
    EXPECT_EQ(intact.runs.size(), 3u);
    ASSERT_EQ(intact.warnings.size(), 1u);
    EXPECT_NE(intact.warnings[0].find(": has no .mhbench-study; its files were checked against store.bin"),
              std::string::npos)
        << intact.warnings[0];
    const auto refused = [&](const std::string& name, const std::string& why) {
        try {
            (void)load_study(dir);
            ADD_FAILURE() << name << " was read";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(name + why), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("run the study's command again to render it from store.bin"),
                      std::string::npos)
                << e.what();
        }
        write_bytes(dir / name, bytes_of(reference / name));
    };
    for (const char* name : {"curves.csv", "checkpoints.csv", "improvements.csv", "timings.csv"}) {
        const std::string bytes = bytes_of(reference / name);
        write_bytes(dir / name, bytes.substr(0, bytes.rfind('\n', bytes.size() - 2) + 1)); // its last line
        refused(name, ", line ");
    }
    fs::remove(dir / "improvements.csv");
    refused("improvements.csv", ": is missing, but store.bin holds lines of it");
    EXPECT_EQ(load_study(dir).warnings.size(), 1u);

    open_study(dir, 3).finish(); // the same command restores the marker
    expect_same_files(dir, reference);
    EXPECT_TRUE(load_study(dir).warnings.empty());
    fs::remove(dir / ".mhbench-study");
    fs::remove(dir / "store.bin");
    const StudyData earlier = load_study(dir);
    EXPECT_EQ(earlier.runs.size(), 3u);
    EXPECT_TRUE(earlier.warnings.empty());
}

TEST(StoreIntegrity, NoTemporaryFileSurvivesAnError) {
    const fs::path dir = fresh_store_integrity_dir("temporaries");
    StudyWriter w = open_study(dir, 1);
    w.append(make_pso_sphere_record(0), 0.5);
    fs::create_directory(dir / "runs.csv"); // the last rename fails
    EXPECT_THROW(w.finish(), std::runtime_error);
    EXPECT_FALSE(has_temporary_files(dir));
    fs::remove(dir / "runs.csv");
    fs::create_directory(dir / "checkpoints.csv.tmp"); // opening the third file fails
    EXPECT_THROW(w.finish(), std::runtime_error);
    fs::remove(dir / "checkpoints.csv.tmp");
    EXPECT_FALSE(has_temporary_files(dir));
    // write_file_atomically: a target it cannot replace.
    fs::create_directory(dir / "a_directory");
    EXPECT_THROW(write_file_atomically(dir / "a_directory", "text"), std::runtime_error);
    EXPECT_THROW(write_file_atomically(dir / "no_such_folder" / "file", "text"), std::runtime_error);
    EXPECT_FALSE(has_temporary_files(dir));
    w.finish(); // and the study is still whole
    EXPECT_EQ(load_study(dir).runs.size(), 1u);
}

} // namespace
} // namespace mhb
