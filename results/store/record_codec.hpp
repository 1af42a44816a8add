// A RunRecord as bytes and back, exactly: every double bit for bit (NaN payloads, -0.0 and
// infinities included), every optional and vector as it was. The study store keeps finished runs
// in this form, so that a report rebuilt later, with other parameter columns, renders the same
// text as one written at once; MPI ranks send records to the writer in it.
//
// The format is little-endian, length-prefixed and versioned by the store's block header; it is
// not meant to be read by anything but decode_record. It grows by sections rather than by a new
// block version: after the fields every record has always had come sections, each a tag and a
// length-prefixed body, then the tag 0. Tag 1 is the ImprovementTrace, tags 2 and up each a field
// of run_fields.hpp added since. The fields every record has had are format 3's core fields of
// run_fields.hpp (in their core order), the curve, the checkpoints and wall_seconds. A reader
// skips a section it does not know, and mhbench builds from before sections (whose records end at
// wall_seconds, as the blocks they stored do) read newer blocks and ignore the sections; a new
// block version would instead have made them cut every newer block off a store as a torn write.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "results/store/run_record.hpp"

namespace mhb {

// Appends primitive values to a byte string.
class ByteWriter {
public:
    void u64(std::uint64_t value);
    void i64(std::int64_t value) { u64(static_cast<std::uint64_t>(value)); }
    void f64(double value);
    void text(std::string_view value);
    void doubles(const std::vector<double>& values); // the count, then each value
    [[nodiscard]] const std::string& bytes() const { return bytes_; }
    [[nodiscard]] std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

// Reads them back; every read past the end throws std::runtime_error naming `what`.
class ByteReader {
public:
    ByteReader(std::string_view bytes, std::string what) : bytes_(bytes), what_(std::move(what)) {}
    std::uint64_t u64();
    std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
    double f64();
    std::string text();
    void skip_text(); // a text() not kept
    std::vector<double> doubles();
    // A count of what follows, bounded so that corrupt bytes give an error rather than a huge
    // allocation.
    std::uint64_t count();
    [[nodiscard]] bool at_end() const { return position_ == bytes_.size(); }

private:
    void need(std::size_t n) const;
    std::string_view bytes_;
    std::string what_;
    std::size_t position_ = 0;
};

void encode_record(ByteWriter& out, const RunRecord& record, double wall_seconds);
std::string encode_record(const RunRecord& record, double wall_seconds);

struct DecodedRecord {
    RunRecord record;
    double wall_seconds = 0.0;
};
// Throws std::runtime_error when the bytes are truncated or malformed. `from_store`: the bytes are
// a store block's, which may end at wall_seconds (stored before sections); anywhere else, such as
// in a message between MPI ranks, that would be a truncation.
DecodedRecord decode_record(ByteReader& in, bool from_store = false);
DecodedRecord decode_record(std::string_view bytes);
// Whether the record that starts at `in` is a successful run, read from its first fields alone
// (the store's index asks this of every block, and a record may hold 10^5 curve points).
bool record_succeeded(ByteReader& in);

} // namespace mhb
