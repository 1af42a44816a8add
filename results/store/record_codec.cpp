#include "results/store/record_codec.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "results/store/run_field_codec.hpp"

namespace mhb {
namespace {

// Bounds on counts read back, so that corrupt bytes give an error rather than a huge allocation.
constexpr std::uint64_t max_count = std::uint64_t{1} << 40;

// The sections after wall_seconds (see record_codec.hpp); the fields' come after these.
enum Section : std::uint64_t { end_of_sections = 0, improvements_section = 1 };
static_assert(improvements_section < first_field_section);

void write_improvements(ByteWriter& out, const ImprovementTrace& trace) {
    ByteWriter body;
    body.u64(trace.points.size());
    for (const auto& p : trace.points) {
        body.i64(p.evaluations);
        body.f64(p.best_f);
    }
    body.f64(trace.last_f);
    out.u64(improvements_section);
    out.text(body.bytes());
}

ImprovementTrace decode_improvements(std::string_view bytes) {
    ByteReader in(bytes, "record: improvements");
    ImprovementTrace trace;
    const std::uint64_t n = in.count();
    trace.points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(n, 1u << 16)));
    for (std::uint64_t i = 0; i < n; ++i) {
        CheckpointSample p;
        p.evaluations = in.i64();
        p.best_f = in.f64();
        trace.points.push_back(p);
    }
    trace.last_f = in.f64();
    if (!in.at_end())
        throw std::runtime_error("record: improvements: " + std::to_string(bytes.size()) +
                                 " bytes hold more than the trace");
    return trace;
}

} // namespace

void ByteWriter::u64(std::uint64_t value) {
    for (int i = 0; i < 8; ++i)
        bytes_.push_back(static_cast<char>((value >> (8 * i)) & 0xffU));
}

void ByteWriter::f64(double value) {
    u64(std::bit_cast<std::uint64_t>(value));
}

void ByteWriter::text(std::string_view value) {
    u64(value.size());
    bytes_.append(value);
}

void ByteWriter::doubles(const std::vector<double>& values) {
    u64(values.size());
    for (const double v : values)
        f64(v);
}

void ByteReader::need(std::size_t n) const {
    if (bytes_.size() - position_ < n)
        throw std::runtime_error(what_ + ": truncated (" + std::to_string(n) +
                                 " more bytes expected at byte " + std::to_string(position_) + " of " +
                                 std::to_string(bytes_.size()) + ")");
}

std::uint64_t ByteReader::u64() {
    need(8);
    std::uint64_t value = 0;
    for (std::size_t i = 0; i < 8; ++i)
        value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[position_ + i])) << (8 * i);
    position_ += 8;
    return value;
}

double ByteReader::f64() {
    return std::bit_cast<double>(u64());
}

std::string ByteReader::text() {
    const std::uint64_t n = u64();
    need(n);
    std::string value(bytes_.substr(position_, n));
    position_ += n;
    return value;
}

void ByteReader::skip_text() {
    const std::uint64_t n = u64();
    need(n);
    position_ += n;
}

std::uint64_t ByteReader::count() {
    const std::uint64_t n = u64();
    if (n > max_count)
        throw std::runtime_error("record: a count of " + std::to_string(n) + " is corrupt");
    return n;
}

std::vector<double> ByteReader::doubles() {
    const std::uint64_t n = u64();
    if (n > max_count)
        throw std::runtime_error("record: a vector length of " + std::to_string(n) + " is corrupt");
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(n, 1u << 16)));
    for (std::uint64_t i = 0; i < n; ++i)
        values.push_back(f64());
    return values;
}

void encode_record(ByteWriter& out, const RunRecord& r, double wall_seconds) {
    encode_core_fields(out, r);
    out.u64(r.curve.size());
    for (const auto& p : r.curve) {
        out.i64(p.iteration);
        out.i64(p.evaluations);
        out.f64(p.best_f);
        out.doubles(p.best_x);
    }
    out.u64(r.checkpoints.size());
    for (const auto& c : r.checkpoints) {
        out.i64(c.evaluations);
        out.f64(c.best_f);
    }
    out.f64(wall_seconds);
    if (r.improvements)
        write_improvements(out, *r.improvements);
    encode_field_sections(out, r);
    out.u64(end_of_sections);
}

std::string encode_record(const RunRecord& record, double wall_seconds) {
    ByteWriter out;
    encode_record(out, record, wall_seconds);
    return out.take();
}

DecodedRecord decode_record(ByteReader& in, bool from_store) {
    DecodedRecord d;
    RunRecord& r = d.record;
    decode_core_fields(in, r);
    for (std::uint64_t i = 0, n = in.count(); i < n; ++i) {
        CurvePoint p;
        p.iteration = in.i64();
        p.evaluations = in.i64();
        p.best_f = in.f64();
        p.best_x = in.doubles();
        r.curve.push_back(std::move(p));
    }
    for (std::uint64_t i = 0, n = in.count(); i < n; ++i) {
        CheckpointSample c;
        c.evaluations = in.i64();
        c.best_f = in.f64();
        r.checkpoints.push_back(c);
    }
    d.wall_seconds = in.f64();
    // A record stored before sections existed ends here, at the end of its block.
    if (from_store && in.at_end())
        return d;
    while (true) {
        const std::uint64_t section = in.u64();
        if (section == end_of_sections)
            break;
        const std::string body = in.text();
        if (section == improvements_section)
            r.improvements = decode_improvements(body);
        else // a field's (or one a newer mhbench added: skipped, as this one's were by older ones)
            decode_field_section(section, body, r);
    }
    return d;
}

bool record_succeeded(ByteReader& in) {
    return decode_ok(in);
}

DecodedRecord decode_record(std::string_view bytes) {
    ByteReader in(bytes, "record");
    DecodedRecord d = decode_record(in);
    if (!in.at_end())
        throw std::runtime_error("record: " + std::to_string(bytes.size()) +
                                 " bytes hold more than one record");
    return d;
}

} // namespace mhb
