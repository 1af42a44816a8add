// The fields of run_fields.hpp as a record's bytes, for record_codec.cpp: the core fields in their
// core order, where every record has them, and each field added since format 3 as a section of
// its own. Each function takes the list of fields, run_fields by default, so that a test can
// declare a field the list does not have yet. Internal to results/store.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "results/store/record_codec.hpp"
#include "results/store/run_fields.hpp"

namespace mhb {

// The tag of the first field's section: 0 ends the sections, 1 is the improvement trace.
inline constexpr std::uint64_t first_field_section = 2;

void encode_core_fields(ByteWriter& out, const RunRecord& r, std::span<const RunField> fields = run_fields);
void decode_core_fields(ByteReader& in, RunRecord& r, std::span<const RunField> fields = run_fields);

// The core fields up to RunRecord::ok read, the others skipped, and ok returned.
bool decode_ok(ByteReader& in, std::span<const RunField> fields = run_fields);

// Each field with a section whose value is not its default, as its tag and its value's bytes.
void encode_field_sections(ByteWriter& out, const RunRecord& r,
                           std::span<const RunField> fields = run_fields);
// `body` decoded into the field whose section is `tag`; any other tag is a section a newer mhbench
// added, and is skipped.
void decode_field_section(std::uint64_t tag, std::string_view body, RunRecord& r,
                          std::span<const RunField> fields = run_fields);

} // namespace mhb
