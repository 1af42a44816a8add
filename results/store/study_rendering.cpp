// StudyWriter::finish(): the sorted result files (runs.csv, curves.csv, checkpoints.csv,
// trajectories.csv, improvements.csv, timings.csv) rendered from store.bin, and the marker that
// names them (see study_writer.hpp and study_marker.hpp).
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <deque>
#include <fstream>
#include <memory>
#include <numeric>
#include <oneapi/tbb/parallel_pipeline.h>
#include <span>
#include <stdexcept>
#include <tuple>

#include "results/store/crc32c.hpp"
#include "results/store/csv.hpp"
#include "results/store/durable_file.hpp"
#include "results/store/record_codec.hpp"
#include "results/store/rendered_lines.hpp"
#include "results/store/run_key.hpp"
#include "results/store/store_block.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_marker.hpp"
#include "results/store/study_writer.hpp"
#include "results/store/study_writer_internal.hpp"

namespace mhb {
namespace fs = std::filesystem;

namespace {

// Adds a run's lines to `text` and counts it in `summary`.
void add_run(RenderedLines& text, StudySummary& summary, DecodedRecord decoded,
             const std::vector<std::string>& columns) {
    RunRecord& record = decoded.record;
    text.append(render_run(record, decoded.wall_seconds, columns));
    ++summary.runs;
    summary.evaluations += record.evaluations;
    if (!record.ok) {
        ++summary.failed;
        if (summary.first_failures.size() < 3) {
            record.curve.clear();
            record.checkpoints.clear();
            record.improvements.reset();
            summary.first_failures.push_back(std::move(record));
        }
    }
}

void add_summary(StudySummary& total, StudySummary& part) {
    total.runs += part.runs;
    total.failed += part.failed;
    total.evaluations += part.evaluations;
    for (auto& failure : part.first_failures)
        if (total.first_failures.size() < 3)
            total.first_failures.push_back(std::move(failure));
}

// Where a stored payload lies in store.bin.
struct ByteRange {
    std::uint64_t offset = 0;
    std::uint64_t size = 0;
};

// The bytes of each range, read with one pread per group of neighbouring ranges (runs finish, and
// are stored, roughly in run order). The views point into `buffers`, a deque: growing it moves no
// string they point into.
std::vector<std::string_view> read_neighbouring(const StoreReader& in, const std::vector<ByteRange>& ranges,
                                                std::deque<std::string>& buffers) {
    std::vector<std::string_view> payloads(ranges.size());
    std::vector<std::size_t> by_offset(ranges.size());
    std::iota(by_offset.begin(), by_offset.end(), std::size_t{0});
    std::sort(by_offset.begin(), by_offset.end(),
              [&](std::size_t a, std::size_t b) { return ranges[a].offset < ranges[b].offset; });
    constexpr std::uint64_t gap = 1 << 12;
    constexpr std::uint64_t limit = std::uint64_t{8} << 20;
    for (std::size_t g = 0; g < by_offset.size();) {
        const std::uint64_t start = ranges[by_offset[g]].offset;
        std::uint64_t stop = start + ranges[by_offset[g]].size;
        std::size_t h = g + 1;
        while (h < by_offset.size()) {
            const ByteRange& neighbour = ranges[by_offset[h]];
            if (neighbour.offset > stop + gap || neighbour.offset + neighbour.size - start > limit)
                break;
            stop = std::max(stop, neighbour.offset + neighbour.size);
            ++h;
        }
        buffers.emplace_back();
        in.read(start, stop - start, buffers.back());
        for (std::size_t i = g; i < h; ++i) {
            const ByteRange& range = ranges[by_offset[i]];
            payloads[by_offset[i]] = std::string_view(buffers.back())
                                         .substr(static_cast<std::size_t>(range.offset - start),
                                                 static_cast<std::size_t>(range.size));
        }
        g = h;
    }
    return payloads;
}

// A result file, streamed to its temporary name and renamed once all are written.
struct Output {
    fs::path path;
    fs::path temporary;
    std::ofstream out;
    RenderedFile written; // size and checksum of what went to `out`, for the marker
    void put(std::string_view text) {
        out << text;
        written.size += text.size();
        written.checksum = crc32c(text, written.checksum);
    }
};

// The temporary files not renamed yet: whatever fails on the way, none stays behind.
struct Temporaries {
    std::vector<fs::path> paths;
    Temporaries() = default;
    Temporaries(const Temporaries&) = delete;
    Temporaries& operator=(const Temporaries&) = delete;
    ~Temporaries() {
        std::error_code ignored;
        for (const auto& path : paths)
            fs::remove(path, ignored);
    }
};

Output open_output(const fs::path& dir, const char* name, Temporaries& temporaries) {
    Output o;
    o.path = dir / name;
    o.temporary = dir / (std::string(name) + ".tmp");
    o.written.name = name;
    errno = 0;
    o.out.open(o.temporary, std::ios::binary | std::ios::trunc);
    if (!o.out)
        throw std::runtime_error(o.path.string() + ": cannot be written (" +
                                 (errno != 0 ? std::strerror(errno) : "unknown reason") + ")");
    temporaries.paths.push_back(o.temporary);
    return o;
}

// The files rendered from the store.
struct ResultFiles {
    Output runs;
    Output curves;
    Output checkpoints;
    Output trajectories;
    Output improvements;
    Output timings;

    void put(const RenderedLines& text) {
        runs.put(text.run_line);
        curves.put(text.curve_lines);
        checkpoints.put(text.checkpoint_lines);
        trajectories.put(text.trajectory_lines);
        improvements.put(text.improvement_lines);
        timings.put(text.timing_line);
    }
};

// Every result file opened under its temporary name, with its header written.
ResultFiles open_result_files(const fs::path& dir, const std::vector<std::string>& parameter_columns,
                              Temporaries& temporaries) {
    ResultFiles files{open_output(dir, StudyFiles::runs, temporaries),
                      open_output(dir, StudyFiles::curves, temporaries),
                      open_output(dir, StudyFiles::checkpoints, temporaries),
                      open_output(dir, StudyFiles::trajectories, temporaries),
                      open_output(dir, StudyFiles::improvements, temporaries),
                      open_output(dir, StudyFiles::timings, temporaries)};
    files.put(rendered_headers(parameter_columns));
    return files;
}

// Closes the result files and gives each its name, runs.csv last, just after the marker that
// names the study and what each file holds.
void publish_result_files(ResultFiles& files, Temporaries& temporaries, const fs::path& dir,
                          std::string_view study_text, std::int64_t runs) {
    // The rendered files are not synced: the store they come from is, and the marker (synced
    // before runs.csv appears) holds each one's size and checksum, so that load_study refuses one
    // that a crash of the machine left short or stale. Syncing them cost 5-8 % of a study of
    // 10^5 short runs (BENCHMARKS.md).
    std::vector<RenderedFile> rendered;
    for (Output* o : {&files.curves, &files.checkpoints, &files.trajectories, &files.improvements,
                      &files.timings, &files.runs}) {
        o->out.close();
        if (!o->out)
            throw std::runtime_error(o->path.string() + ": writing failed (" + std::strerror(errno) + ")");
        rendered.push_back(o->written);
        if (o == &files.runs) // the study this runs.csv belongs to, and what it and the others hold
            write_file_atomically(dir / StudyFiles::marker, study_marker(study_text, runs, rendered));
        std::error_code ec;
        fs::rename(o->temporary, o->path, ec);
        if (ec)
            throw std::runtime_error(o->path.string() + ": cannot be written (" + ec.message() + ")");
        std::erase(temporaries.paths, o->temporary);
    }
    sync_directory(dir);
}

} // namespace

std::vector<std::int64_t> StudyWriter::runs_to_render() const {
    if (!keys_) // runs named by run_id alone: the study is what was stored
        return {completed_.begin(), completed_.end()};
    std::vector<std::int64_t> ids;
    if (keys_->run_ids) {
        ids = *keys_->run_ids;
        std::sort(ids.begin(), ids.end());
    } else {
        ids.resize(static_cast<std::size_t>(keys_->count));
        for (std::size_t i = 0; i < ids.size(); ++i)
            ids[i] = static_cast<std::int64_t>(i);
    }
    for (const std::int64_t id : ids)
        if (id < 0 || id >= keys_->count || index_.count(identities_[static_cast<std::size_t>(id)]) == 0)
            throw std::runtime_error((dir_ / StudyFiles::store).string() + ": holds no record of " +
                                     run_name(id) +
                                     " of study.ini; run the same command again to compute it");
    return ids;
}

void StudyWriter::finish() {
    const std::lock_guard<std::mutex> lock(mutex_);
    {
        const std::lock_guard<std::mutex> syncing(sync_mutex_);
        sync_store();
    }
    const std::vector<std::int64_t> ids = runs_to_render();
    // Another process writing into this directory (it should hold the lock) could have put its
    // study.ini beside the runs of this one.
    if (read_whole_file(dir_ / StudyFiles::study) != study_text_)
        throw std::runtime_error((dir_ / StudyFiles::study).string() +
                                 ": was replaced while this study ran (another mhbench writing into the "
                                 "same directory?); nothing was rendered");
    render_files(ids);
}

DecodedRecord StudyWriter::stored_record(std::int64_t run_id, std::string_view payload) const {
    if (check_payload(payload) == PayloadCheck::damaged)
        throw std::runtime_error((dir_ / StudyFiles::store).string() + ": the record of " + run_name(run_id) +
                                 " was damaged while the study ran; run the same command again");
    ByteReader reader(payload, (dir_ / StudyFiles::store).string());
    for (int skipped = 0; skipped < 4; ++skipped) // identity, slot, facts, notes
        reader.text();
    DecodedRecord decoded = decode_record(reader, true);
    // The record as this study names it: a run found by identity may come from a study that
    // numbered it differently or read its data file from another path.
    RunRecord& record = decoded.record;
    record.run_id = run_id;
    if (keys_) {
        if (keys_->names) {
            std::tie(record.algorithm, record.problem) = keys_->names(run_id);
        } else {
            const RunKey key = keys_->key(run_id);
            record.algorithm = key.algorithm;
            record.problem = key.problem;
        }
    }
    return decoded;
}

std::optional<RunRecord> StudyWriter::stored_run(std::int64_t run_id) {
    Stored stored;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto found = index_.find(keys_ ? identities_.at(static_cast<std::size_t>(run_id))
                                             : key_of(run_id, nullptr).identity);
        if (found == index_.end())
            return std::nullopt;
        stored = found->second;
    }
    std::string payload;
    StoreReader(dir_ / StudyFiles::store).read(stored.offset, stored.size, payload);
    return stored_record(run_id, payload).record;
}

void StudyWriter::render_only(std::vector<std::int64_t> run_ids) {
    if (!keys_)
        throw std::logic_error("StudyWriter::render_only needs a study with run keys");
    keys_->run_ids = std::move(run_ids);
}

struct StudyWriter::RenderedChunk {
    RenderedLines text;
    StudySummary summary;
};

StudyWriter::RenderedChunk StudyWriter::render_chunk(const StoreReader& in,
                                                     std::span<const std::int64_t> ids) const {
    std::vector<std::int64_t> stored_ids;
    std::vector<ByteRange> ranges;
    for (const std::int64_t id : ids) {
        const auto found =
            index_.find(keys_ ? identities_[static_cast<std::size_t>(id)] : key_of(id, nullptr).identity);
        if (found != index_.end()) {
            stored_ids.push_back(id);
            ranges.push_back({found->second.offset, found->second.size});
        }
    }
    std::deque<std::string> buffers;
    const std::vector<std::string_view> payloads = read_neighbouring(in, ranges, buffers);
    RenderedChunk out;
    for (std::size_t i = 0; i < payloads.size(); ++i)
        add_run(out.text, out.summary, stored_record(stored_ids[i], payloads[i]), parameter_columns_);
    return out;
}

void StudyWriter::render_files(const std::vector<std::int64_t>& ids) {
    const StoreReader in(dir_ / StudyFiles::store);
    // Each file is streamed to its temporary name and renamed at the end, runs.csv last. Whatever
    // fails on the way, no temporary file stays behind.
    Temporaries temporaries;
    ResultFiles files = open_result_files(dir_, parameter_columns_, temporaries);
    summary_ = StudySummary{};
    // Records are decoded and rendered in parallel, a chunk of runs at a time, and written in
    // run_id order: the output is the same bytes as a serial loop's.
    using Chunk = std::span<const std::int64_t>;
    constexpr std::size_t chunk_size = 512;
    std::size_t next = 0;
    tbb::parallel_pipeline(
        16, tbb::make_filter<void, Chunk>(tbb::filter_mode::serial_in_order,
                                          [&](tbb::flow_control& control) {
                                              if (next >= ids.size()) {
                                                  control.stop();
                                                  return Chunk{};
                                              }
                                              const std::size_t first = next;
                                              next = std::min(ids.size(), next + chunk_size);
                                              return Chunk(ids).subspan(first, next - first);
                                          }) &
                tbb::make_filter<Chunk, std::shared_ptr<RenderedChunk>>(
                    tbb::filter_mode::parallel,
                    [&](Chunk chunk) { return std::make_shared<RenderedChunk>(render_chunk(in, chunk)); }) &
                tbb::make_filter<std::shared_ptr<RenderedChunk>, void>(
                    tbb::filter_mode::serial_in_order, [&](const std::shared_ptr<RenderedChunk>& part) {
                        files.put(part->text);
                        add_summary(summary_, part->summary);
                    }));
    publish_result_files(files, temporaries, dir_, study_text_, static_cast<std::int64_t>(ids.size()));
}

} // namespace mhb
