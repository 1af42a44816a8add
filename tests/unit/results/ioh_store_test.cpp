// The improvement record in the study store: the record's section (and records stored before
// sections existed), improvements.csv, and a store written before improvements were recorded,
// which still loads, resumes and exports (its runs from their grid, marked approximate).
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>

#include "results/exports/ioh_export.hpp"
#include "results/store/csv.hpp"
#include "results/store/record_codec.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_marker.hpp"
#include "results/store/study_writer.hpp"
#include "support/numbers.hpp"

namespace mhb {
namespace {

namespace fs = std::filesystem;

using mhb::test_support::inf;

fs::path fresh_ioh_store_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("mhb_ioh_store_" + name);
    fs::remove_all(dir);
    return dir;
}

RunRecord record(std::int64_t id, std::int64_t index, bool with_improvements) {
    RunRecord r;
    r.run_id = id;
    r.algorithm = "de";
    r.problem = "sphere:dim=2";
    r.budget = "evaluations=20";
    r.run_index = index;
    r.seed = 7 + static_cast<std::uint64_t>(index);
    r.best_f = 0.5;
    r.f_opt = 0.0;
    r.best_x = {0.5, 0.5};
    r.evaluations = 20;
    r.iterations = 2;
    r.curve = {{0, 10, 2.0, {}}, {1, 20, 0.5, {}}};
    r.checkpoints = {{1, 9.0}, {10, 2.0}, {20, 0.5}};
    if (with_improvements)
        r.improvements = ImprovementTrace{{{1, 9.0}, {3, 2.0}, {17, 0.5}}, 4.0};
    return r;
}

void expect_same_trace(const std::optional<ImprovementTrace>& a, const std::optional<ImprovementTrace>& b) {
    ASSERT_EQ(a.has_value(), b.has_value());
    if (!a)
        return;
    ASSERT_EQ(a->points.size(), b->points.size());
    for (std::size_t i = 0; i < a->points.size(); ++i) {
        EXPECT_EQ(a->points[i].evaluations, b->points[i].evaluations);
        EXPECT_EQ(a->points[i].best_f, b->points[i].best_f);
    }
    EXPECT_EQ(a->last_f, b->last_f);
}

TEST(IohStore, ImprovementsRoundTripThroughTheRecordCodec) {
    RunRecord r = record(0, 0, true);
    r.improvements->points.push_back({19, -inf});
    r.improvements->last_f = inf;
    const DecodedRecord back = decode_record(encode_record(r, 1.5));
    expect_same_trace(back.record.improvements, r.improvements);
    EXPECT_EQ(back.wall_seconds, 1.5);
    EXPECT_FALSE(decode_record(encode_record(record(0, 0, false), 1.0)).record.improvements.has_value());
    // Records one after another in one buffer (as MPI ranks send them).
    ByteWriter out;
    encode_record(out, r, 1.0);
    encode_record(out, record(1, 1, false), 2.0);
    ByteReader in(out.bytes(), "test");
    expect_same_trace(decode_record(in).record.improvements, r.improvements);
    EXPECT_FALSE(decode_record(in).record.improvements.has_value());
    EXPECT_TRUE(in.at_end());
}

TEST(IohStore, ARecordStoredBeforeSectionsReadsWithoutImprovements) {
    // Before sections, a record ended at wall_seconds: the bytes of today's without its end tag.
    const RunRecord r = record(3, 1, false);
    std::string bytes = encode_record(r, 2.5);
    bytes.resize(bytes.size() - 8);
    ByteReader in(bytes, "store block");
    const DecodedRecord back = decode_record(in, true);
    EXPECT_TRUE(in.at_end());
    EXPECT_FALSE(back.record.improvements.has_value());
    EXPECT_EQ(back.record.run_id, 3);
    EXPECT_EQ(back.record.checkpoints.size(), 3u);
    EXPECT_EQ(back.wall_seconds, 2.5);
    // Anywhere but in a store block (a message between MPI ranks), such bytes are cut short.
    EXPECT_THROW((void)decode_record(bytes), std::runtime_error);
}

TEST(IohStore, ASectionFromANewerMhbenchIsSkipped) {
    const RunRecord r = record(0, 0, true);
    std::string bytes = encode_record(r, 1.0);
    bytes.resize(bytes.size() - 8); // before the end tag: a section this build does not know
    ByteWriter extra;
    extra.u64(99);
    extra.text("anything");
    extra.u64(0);
    const DecodedRecord back = decode_record(bytes + extra.bytes());
    expect_same_trace(back.record.improvements, r.improvements);
}

TEST(IohStore, StudyFilesKeepTheImprovementsExactly) {
    const fs::path dir = fresh_ioh_store_dir("files");
    RunRecord a = record(0, 0, true);
    a.improvements->points.push_back({19, -inf});
    a.improvements->last_f = inf;
    RunRecord failed = record(2, 2, false);
    failed.ok = false;
    failed.message = "boom";
    {
        StudyWriter writer(dir, "study", "context", {}, false);
        writer.append(a, 1.0);
        writer.append(record(1, 1, false), 1.0);
        writer.append(failed, 1.0);
        writer.finish();
    }
    std::ifstream in(dir / StudyFiles::improvements);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "run_id,event,evaluations,f\n0,improvement,1,9\n0,improvement,3,2\n"
                          "0,improvement,17,0.5\n0,improvement,19,-inf\n0,last,20,inf\n");
    const StudyData data = load_study(dir);
    ASSERT_EQ(data.runs.size(), 3u);
    expect_same_trace(data.runs[0].improvements, a.improvements);
    EXPECT_FALSE(data.runs[1].improvements.has_value());
    EXPECT_FALSE(data.runs[2].improvements.has_value());
}

TEST(IohStore, AMalformedImprovementsFileIsOneClearError) {
    const fs::path dir = fresh_ioh_store_dir("malformed");
    {
        StudyWriter writer(dir, "study", "context", {}, false);
        writer.append(record(0, 0, true), 1.0);
        writer.finish();
    }
    // As a study from before the marker held the rendered files' checksums, so that the edited
    // file reaches the reader's own checks.
    write_file_atomically(dir / StudyFiles::marker, study_marker("study", 1));
    const auto expect_error = [&](const std::string& content, const std::string& part) {
        std::ofstream(dir / StudyFiles::improvements) << content;
        try {
            (void)load_study(dir);
            ADD_FAILURE() << "no error for " << content;
        } catch (const std::runtime_error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(part), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    };
    expect_error("run_id,event,evaluations,f\n0,better,1,9\n", "'better' is not improvement or last");
    expect_error("run_id,event,evaluations,f\n0,improvement,3,9\n0,improvement,2,8\n", "line 3");
    expect_error("run_id,event,evaluations,f\n0,improvement,1,9\n0,improvement,2,9\n", "not an improvement");
    expect_error("run_id,event,evaluations,f\n5,improvement,1,9\n", "run_id 5 is not in runs.csv");
}

// store.bin as an mhbench from before improvements wrote it: one block per run, whose record ends
// at wall_seconds, keyed (without run keys) by "run <id> of study <hash of the study text>".
void write_old_store(const fs::path& dir, const std::string& study_text, const std::vector<RunRecord>& runs) {
    fs::create_directories(dir);
    std::ofstream(dir / StudyFiles::marker) << "mhbench study directory, format 3\n";
    std::ofstream store(dir / StudyFiles::store, std::ios::binary);
    for (const RunRecord& r : runs) {
        const std::string identity = "run " + std::to_string(r.run_id) + " of study " +
                                     std::to_string(std::hash<std::string>{}(study_text));
        ByteWriter payload;
        payload.text(identity);
        payload.text(identity);
        payload.text("");
        payload.text("");
        std::string bytes = payload.take();
        std::string record_bytes = encode_record(r, 1.0);
        record_bytes.resize(record_bytes.size() - 8); // no sections, no end tag
        bytes += record_bytes;
        ByteWriter size;
        size.u64(bytes.size());
        store << "MHBRUN3\n" << size.bytes() << bytes << "MHBEND3\n";
    }
}

TEST(IohStore, AStudyStoredBeforeImprovementsResumesReportsAndExports) {
    const fs::path dir = fresh_ioh_store_dir("old");
    const std::string study_text = "runs = 3\n";
    write_old_store(dir, study_text, {record(0, 0, false), record(1, 1, false)});
    {
        StudyWriter writer(dir, study_text, "context", {}, false);
        EXPECT_EQ(writer.completed(), (std::set<std::int64_t>{0, 1})); // the old runs are kept
        writer.append(record(2, 2, true), 1.0);                        // a new run records improvements
        writer.finish();
    }
    const StudyData data = load_study(dir);
    ASSERT_EQ(data.runs.size(), 3u);
    EXPECT_FALSE(data.runs[0].improvements.has_value());
    EXPECT_FALSE(data.runs[1].improvements.has_value());
    ASSERT_TRUE(data.runs[2].improvements.has_value());
    EXPECT_EQ(data.runs[0].checkpoints.size(), 3u);

    const IohExportSummary summary = write_ioh_export(StudyIndex(data), dir / "ioh");
    EXPECT_EQ(summary.approximate_runs, 2u);
    std::ifstream in(dir / "ioh" / "de" / "data_f101_sphere" / "IOHprofiler_f101_DIM2.dat");
    std::stringstream dat;
    dat << in.rdbuf();
    // Old runs: the grid's improvements (9 at 1, 2 at 10, 0.5 at 20); the new one: exact rows.
    EXPECT_EQ(dat.str(),
              "evaluations raw_y\n1 9.0000000000\n10 2.0000000000\n20 0.5000000000\n"
              "evaluations raw_y\n1 9.0000000000\n10 2.0000000000\n20 0.5000000000\n"
              "evaluations raw_y\n1 9.0000000000\n3 2.0000000000\n17 0.5000000000\n20 4.0000000000\n");

    // A study an older mhbench finished has no improvements.csv at all: read, and exported from grids.
    fs::remove(dir / StudyFiles::improvements);
    const StudyData older = load_study(dir);
    for (const auto& r : older.runs)
        EXPECT_FALSE(r.improvements.has_value());
    EXPECT_EQ(write_ioh_export(StudyIndex(older), dir / "ioh").approximate_runs, 3u);
}

} // namespace
} // namespace mhb
