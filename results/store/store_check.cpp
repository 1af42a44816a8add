// The rendered files of a study without its marker, checked against store.bin (see store_check.hpp).
#include "results/store/store_check.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "results/store/csv.hpp"
#include "results/store/record_codec.hpp"
#include "results/store/rendered_lines.hpp"
#include "results/store/store_block.hpp"
#include "results/store/store_scan.hpp"

namespace mhb {
namespace fs = std::filesystem;

namespace {

// Where a record lies in store.bin.
struct StoredRun {
    std::uint64_t offset = 0;
    std::uint64_t size = 0;
};

// What runs.csv and a stored record both say of the run they are: the study may have numbered
// it differently (run_id), but not named it differently.
std::string run_name(const RunRecord& r) {
    return r.algorithm + '\n' + r.problem + '\n' + r.budget + '\n' + std::to_string(r.run_index) + '\n' +
           std::to_string(r.seed);
}

DecodedRecord decode_stored(std::string_view payload, const fs::path& store) {
    ByteReader reader(payload, store.string());
    for (int skipped = 0; skipped < 4; ++skipped) // identity, slot, facts, notes
        reader.text();
    return decode_record(reader, true);
}

// The records the writer would use, by run name, newest first: of each identity the newest
// block, when its checksum holds (or, before checksums, it decodes).
std::unordered_map<std::string, std::vector<StoredRun>> index_store(const StoreReader& in,
                                                                    const fs::path& store) {
    std::unordered_map<std::string, std::pair<StoredRun, std::string>> by_identity;
    scan_store_blocks(in, fs::file_size(store), [&](std::uint64_t offset, std::string_view payload) {
        if (check_payload(payload) == PayloadCheck::damaged)
            return;
        try {
            std::string identity = ByteReader(payload, store.string()).text();
            by_identity[std::move(identity)] = {{offset, payload.size()},
                                                run_name(decode_stored(payload, store).record)};
        } catch (const std::runtime_error&) { // a block from before checksums that does not decode
        }
    });
    std::unordered_map<std::string, std::vector<StoredRun>> by_name;
    for (const auto& [identity, stored] : by_identity)
        by_name[stored.second].push_back(stored.first);
    for (auto& [name, runs] : by_name)
        std::sort(runs.begin(), runs.end(),
                  [](const StoredRun& a, const StoredRun& b) { return a.offset > b.offset; });
    return by_name;
}

// A rendered file as found, and how much of it has been matched so far.
struct FoundFile {
    fs::path path;
    std::string text;
    bool missing = false; // improvements.csv, absent from studies made before it existed
    std::size_t matched = 0;

    [[nodiscard]] bool continues_with(std::string_view part) const {
        return missing ? part.empty() : std::string_view(text).substr(matched, part.size()) == part;
    }
    // The 1-based line holding the first byte where the file stops being `part`.
    [[nodiscard]] std::size_t line_of_difference(std::string_view part) const {
        const std::string_view rest = std::string_view(text).substr(matched);
        const auto same =
            std::mismatch(rest.begin(), rest.end(), part.begin(), part.end()).first - rest.begin();
        const std::string_view before =
            std::string_view(text).substr(0, matched + static_cast<std::size_t>(same));
        return 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
    }
};

std::vector<FoundFile> read_rendered_files(const fs::path& dir) {
    std::vector<FoundFile> files;
    for (const RenderedFileText& file : rendered_file_texts) {
        FoundFile found{dir / file.name, "", false, 0};
        found.missing = file.name == std::string_view(StudyFiles::improvements) && !fs::exists(found.path);
        if (!found.missing)
            found.text = read_whole_file(found.path);
        files.push_back(std::move(found));
    }
    return files;
}

// The one line that refuses `file`, at `line` (none: the whole file).
std::runtime_error refusal(const fs::path& dir, const FoundFile& file, std::optional<std::size_t> line,
                           const std::string& what) {
    return std::runtime_error(file.path.string() + (line ? ", line " + std::to_string(*line) : "") + ": " +
                              what + " (" + dir.string() + " has no " + StudyFiles::marker +
                              " to vouch for it, so it was checked against " + StudyFiles::store +
                              "); run the study's command again to render it from store.bin");
}

// Every file continues with its part of `lines`: matched, and passed.
bool take(std::vector<FoundFile>& files, const RenderedLines& lines) {
    for (std::size_t k = 0; k < files.size(); ++k)
        if (!files[k].continues_with(lines.*rendered_file_texts[k].text))
            return false;
    for (std::size_t k = 0; k < files.size(); ++k)
        files[k].matched += (lines.*rendered_file_texts[k].text).size();
    return true;
}

// The refusal of the first file that does not continue with its part of `lines`.
std::runtime_error first_difference(const fs::path& dir, const std::vector<FoundFile>& files,
                                    const RenderedLines& lines, const std::string& what) {
    for (std::size_t k = 0; k < files.size(); ++k) {
        const std::string& part = lines.*rendered_file_texts[k].text;
        if (files[k].continues_with(part))
            continue;
        if (files[k].missing)
            return refusal(dir, files[k], std::nullopt, "is missing, but store.bin holds lines of it");
        return refusal(dir, files[k], files[k].line_of_difference(part), "differs from " + what);
    }
    throw std::logic_error("first_difference: the files do not differ");
}

} // namespace

void check_rendered_files_against_store(const fs::path& dir, const StudyData& data,
                                        const std::vector<std::size_t>& run_lines) {
    const fs::path store = dir / StudyFiles::store;
    const StoreReader in(store);
    const auto stored = index_store(in, store);
    std::vector<FoundFile> files = read_rendered_files(dir);
    const RenderedLines headers = rendered_headers(data.parameter_columns);
    if (!take(files, headers))
        throw first_difference(dir, files, headers, "the header mhbench writes");
    std::string payload;
    for (std::size_t i = 0; i < data.runs.size(); ++i) {
        const RunRecord& run = data.runs[i];
        const auto found = stored.find(run_name(run));
        if (found == stored.end())
            throw refusal(dir, files.front(), run_lines[i],
                          "store.bin holds no run " + run.algorithm + ", " + run.problem + ", " + run.budget +
                              ", run " + std::to_string(run.run_index) + ", seed " +
                              std::to_string(run.seed));
        std::optional<RenderedLines> newest; // what the run's newest record renders
        bool matched = false;
        for (const StoredRun& candidate : found->second) {
            in.read(candidate.offset, candidate.size, payload);
            DecodedRecord decoded = decode_stored(payload, store);
            decoded.record.run_id = run.run_id;
            RenderedLines lines = render_run(decoded.record, decoded.wall_seconds, data.parameter_columns);
            matched = take(files, lines);
            if (matched)
                break;
            if (!newest)
                newest = std::move(lines);
        }
        if (!matched)
            throw first_difference(dir, files, *newest,
                                   "store.bin's record of run " + std::to_string(run.run_id));
    }
    for (const FoundFile& file : files)
        if (!file.missing && file.matched != file.text.size())
            throw refusal(dir, file, file.line_of_difference(""), "goes on after the last run of runs.csv");
}

} // namespace mhb
