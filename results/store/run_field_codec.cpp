// The fields of run_fields.hpp as a record's bytes (see run_field_codec.hpp).
#include "results/store/run_field_codec.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

namespace mhb {
namespace {

// What a record is made of can never change for the records already stored: format 3 fixed 17 core
// fields, each at one position, and a field added since goes in a section of its own.
constexpr int format_3_core_fields = 17;

consteval bool stored_once_each() {
    int core = 0;
    for (const RunField& field : run_fields) {
        const bool stored = field.stored.core >= 0 || field.stored.section != 0;
        if (stored == is_computed(field) || (field.stored.core >= 0 && field.stored.section != 0))
            return false;
        if (field.stored.section != 0 && field.stored.section < first_field_section)
            return false;
        for (const RunField& other : run_fields)
            if (&other != &field && other.stored.section != 0 && other.stored.section == field.stored.section)
                return false;
        core += field.stored.core >= 0 ? 1 : 0;
    }
    for (int position = 0; position < core; ++position) {
        int at_position = 0;
        for (const RunField& field : run_fields)
            at_position += field.stored.core == position ? 1 : 0;
        if (at_position != 1)
            return false;
    }
    return core == format_3_core_fields;
}
static_assert(stored_once_each(), "run_fields: format 3's 17 core fields, each at its own position 0-16, and "
                                  "each field added since in a section of its own (tag 2, 3, ...); a "
                                  "computed field is not stored");

// One value as bytes, by its type (run_fields.hpp).
void encode_value(ByteWriter& out, std::int64_t value) {
    out.i64(value);
}
void encode_value(ByteWriter& out, std::uint64_t value) {
    out.u64(value);
}
void encode_value(ByteWriter& out, bool value) {
    out.u64(value ? 1 : 0);
}
void encode_value(ByteWriter& out, double value) {
    out.f64(value);
}
void encode_value(ByteWriter& out, const std::string& value) {
    out.text(value);
}
void encode_value(ByteWriter& out, const std::vector<double>& values) {
    out.doubles(values);
}
void encode_value(ByteWriter& out, const std::vector<std::string>& texts) {
    out.u64(texts.size());
    for (const auto& text : texts)
        out.text(text);
}
// Set or not, then the value: an unset one takes as many bytes as a set one.
template <class T> void encode_value(ByteWriter& out, const std::optional<T>& value) {
    out.u64(value ? 1 : 0);
    encode_value(out, value.value_or(T{}));
}

void decode_value(ByteReader& in, std::int64_t& value) {
    value = in.i64();
}
void decode_value(ByteReader& in, std::uint64_t& value) {
    value = in.u64();
}
void decode_value(ByteReader& in, bool& value) {
    value = in.u64() != 0;
}
void decode_value(ByteReader& in, double& value) {
    value = in.f64();
}
void decode_value(ByteReader& in, std::string& value) {
    value = in.text();
}
void decode_value(ByteReader& in, std::vector<double>& values) {
    values = in.doubles();
}
void decode_value(ByteReader& in, std::vector<std::string>& texts) {
    texts.clear();
    for (std::uint64_t i = 0, n = in.count(); i < n; ++i)
        texts.push_back(in.text());
}
template <class T> void decode_value(ByteReader& in, std::optional<T>& value) {
    const bool set = in.u64() != 0;
    T stored{};
    decode_value(in, stored);
    value = set ? std::optional<T>(stored) : std::nullopt;
}

void encode_field(ByteWriter& out, const RunRecord& r, const RunField& field) {
    std::visit(
        [&](auto member) {
            if constexpr (std::is_member_object_pointer_v<decltype(member)>)
                encode_value(out, r.*member);
        },
        field.member);
}

void decode_field(ByteReader& in, RunRecord& r, const RunField& field) {
    std::visit(
        [&](auto member) {
            if constexpr (std::is_member_object_pointer_v<decltype(member)>)
                decode_value(in, r.*member);
        },
        field.member);
}

// Past a field's bytes without keeping its value (a text is not even copied).
void skip_field(ByteReader& in, const RunField& field) {
    std::visit(
        [&](auto member) {
            if constexpr (std::is_same_v<decltype(member), std::string RunRecord::*>) {
                in.skip_text();
            } else if constexpr (std::is_member_object_pointer_v<decltype(member)>) {
                std::remove_cvref_t<decltype(std::declval<RunRecord&>().*member)> value{};
                decode_value(in, value);
            }
        },
        field.member);
}

// The field at a core position; none past the last.
const RunField* core_field(std::span<const RunField> fields, int position) {
    for (const RunField& field : fields)
        if (field.stored.core == position)
            return &field;
    return nullptr;
}

bool is_ok_field(const RunField& field) {
    const auto* member = std::get_if<bool RunRecord::*>(&field.member);
    return member != nullptr && *member == &RunRecord::ok;
}

} // namespace

void encode_core_fields(ByteWriter& out, const RunRecord& r, std::span<const RunField> fields) {
    for (int position = 0; const RunField* field = core_field(fields, position); ++position)
        encode_field(out, r, *field);
}

void decode_core_fields(ByteReader& in, RunRecord& r, std::span<const RunField> fields) {
    for (int position = 0; const RunField* field = core_field(fields, position); ++position)
        decode_field(in, r, *field);
}

bool decode_ok(ByteReader& in, std::span<const RunField> fields) {
    for (int position = 0; const RunField* field = core_field(fields, position); ++position) {
        if (is_ok_field(*field)) {
            bool ok = false;
            decode_value(in, ok);
            return ok;
        }
        skip_field(in, *field);
    }
    throw std::logic_error("decode_ok: RunRecord::ok is not a core field");
}

void encode_field_sections(ByteWriter& out, const RunRecord& r, std::span<const RunField> fields) {
    static const RunRecord defaults;
    for (const RunField& field : fields) {
        if (field.stored.section == 0)
            continue;
        ByteWriter body;
        encode_field(body, r, field);
        // A value that is the default needs no section (it reads back the same without one), and a
        // record holding only defaults in its added fields keeps the bytes older builds wrote.
        ByteWriter unset;
        encode_field(unset, defaults, field);
        if (body.bytes() == unset.bytes())
            continue;
        out.u64(field.stored.section);
        out.text(body.bytes());
    }
}

void decode_field_section(std::uint64_t tag, std::string_view body, RunRecord& r,
                          std::span<const RunField> fields) {
    for (const RunField& field : fields) {
        if (field.stored.section != tag)
            continue;
        const std::string what = std::string("record: ") + field.column;
        ByteReader in(body, what);
        decode_field(in, r, field);
        if (!in.at_end())
            throw std::runtime_error(what + ": " + std::to_string(body.size()) +
                                     " bytes hold more than the field");
        return;
    }
}

} // namespace mhb
