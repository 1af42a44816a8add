#include "results/store/record_codec.hpp"

#include <bit>
#include <stdexcept>

namespace mhb {
namespace {

// Bounds on counts read back, so that corrupt bytes give an error rather than a huge allocation.
constexpr std::uint64_t max_count = std::uint64_t{1} << 40;

void doubles(ByteWriter& out, const std::vector<double>& values) {
    out.u64(values.size());
    for (const double v : values)
        out.f64(v);
}

std::vector<double> doubles(ByteReader& in) {
    const std::uint64_t n = in.u64();
    if (n > max_count)
        throw std::runtime_error("record: a vector length of " + std::to_string(n) + " is corrupt");
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(n, 1u << 16)));
    for (std::uint64_t i = 0; i < n; ++i)
        values.push_back(in.f64());
    return values;
}

std::uint64_t count(ByteReader& in) {
    const std::uint64_t n = in.u64();
    if (n > max_count)
        throw std::runtime_error("record: a count of " + std::to_string(n) + " is corrupt");
    return n;
}

// The sections after wall_seconds (see record_codec.hpp).
enum Section : std::uint64_t { end_of_sections = 0, improvements_section = 1 };

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
    const std::uint64_t n = count(in);
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

void encode_record(ByteWriter& out, const RunRecord& r, double wall_seconds) {
    out.i64(r.run_id);
    out.text(r.algorithm);
    out.text(r.problem);
    out.text(r.budget);
    out.i64(r.run_index);
    out.u64(r.seed);
    out.u64(r.ok ? 1 : 0);
    out.text(r.message);
    out.f64(r.best_f);
    out.u64(r.f_opt ? 1 : 0);
    out.f64(r.f_opt.value_or(0.0));
    doubles(out, r.x_opt);
    out.i64(r.evaluations);
    out.i64(r.iterations);
    out.u64(r.evaluations_to_target ? 1 : 0);
    out.i64(r.evaluations_to_target.value_or(0));
    doubles(out, r.best_x);
    out.u64(r.parameter_names.size());
    for (const auto& name : r.parameter_names)
        out.text(name);
    doubles(out, r.true_parameters);
    out.u64(r.curve.size());
    for (const auto& p : r.curve) {
        out.i64(p.iteration);
        out.i64(p.evaluations);
        out.f64(p.best_f);
        doubles(out, p.best_x);
    }
    out.u64(r.checkpoints.size());
    for (const auto& c : r.checkpoints) {
        out.i64(c.evaluations);
        out.f64(c.best_f);
    }
    out.f64(wall_seconds);
    if (r.improvements)
        write_improvements(out, *r.improvements);
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
    r.run_id = in.i64();
    r.algorithm = in.text();
    r.problem = in.text();
    r.budget = in.text();
    r.run_index = in.i64();
    r.seed = in.u64();
    r.ok = in.u64() != 0;
    r.message = in.text();
    r.best_f = in.f64();
    const bool has_f_opt = in.u64() != 0;
    const double f_opt = in.f64();
    if (has_f_opt)
        r.f_opt = f_opt;
    r.x_opt = doubles(in);
    r.evaluations = in.i64();
    r.iterations = in.i64();
    const bool has_target = in.u64() != 0;
    const std::int64_t to_target = in.i64();
    if (has_target)
        r.evaluations_to_target = to_target;
    r.best_x = doubles(in);
    for (std::uint64_t i = 0, n = count(in); i < n; ++i)
        r.parameter_names.push_back(in.text());
    r.true_parameters = doubles(in);
    for (std::uint64_t i = 0, n = count(in); i < n; ++i) {
        CurvePoint p;
        p.iteration = in.i64();
        p.evaluations = in.i64();
        p.best_f = in.f64();
        p.best_x = doubles(in);
        r.curve.push_back(std::move(p));
    }
    for (std::uint64_t i = 0, n = count(in); i < n; ++i) {
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
        // Any other section is one a newer mhbench added: skipped, as this one was by older ones.
    }
    return d;
}

bool record_succeeded(ByteReader& in) {
    // The fields before `ok`, in encode_record's order: run_id, algorithm, problem, budget,
    // run_index, seed.
    (void)in.i64();
    for (int text = 0; text < 3; ++text)
        in.skip_text();
    (void)in.i64();
    (void)in.u64();
    return in.u64() != 0;
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
