// The list of a run's fields (results/store/run_fields.hpp) as the record codec and runs.csv use
// it: every field comes back from store.bin bit for bit and from runs.csv as it was written, set
// or unset, and leaves every other field as it was; a runs.csv written before a field existed
// reads as its default. The tests iterate the list, so a field added to it is tested here without
// this file changing.
#include <bit>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "results/store/csv.hpp"
#include "results/store/record_codec.hpp"
#include "results/store/run_field_codec.hpp"
#include "results/store/run_fields.hpp"
#include "results/store/runs_csv.hpp"

namespace mhb {
namespace {

// A value unlike the member's default, of every type a field may have.
void set_distinct(std::int64_t& value) {
    value = -1234567890123;
}
void set_distinct(std::uint64_t& value) {
    value = 0xfedcba9876543210U;
}
void set_distinct(bool& value) {
    value = !value;
}
void set_distinct(double& value) {
    value = -1.0 / 3.0;
}
void set_distinct(std::string& value) {
    value = "a, \"b\" c";
}
void set_distinct(std::optional<double>& value) {
    value = 0.0; // set, and zero: not to be read back as unset
}
void set_distinct(std::optional<std::int64_t>& value) {
    value = 0;
}
void set_distinct(std::vector<double>& values) {
    values = {-1.0 / 3.0, -0.0, 1e300};
}
void set_distinct(std::vector<std::string>& texts) {
    texts = {"Rs", "L d"};
}

// Equal values: doubles bit for bit, or (from runs.csv, whose NaN has no payload) NaN as NaN.
bool same(double a, double b, bool bits) {
    return bits ? std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b)
                : (a == b && std::signbit(a) == std::signbit(b)) || (std::isnan(a) && std::isnan(b));
}
template <class T> bool same(const T& a, const T& b, bool) {
    return a == b;
}
template <class T> bool same(const std::optional<T>& a, const std::optional<T>& b, bool bits) {
    return a.has_value() == b.has_value() && (!a || same(*a, *b, bits));
}
bool same(const std::vector<double>& a, const std::vector<double>& b, bool bits) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same(a[i], b[i], bits))
            return false;
    return true;
}

std::string name_of(const RunField& field) {
    return *field.column != '\0' ? field.column : "field " + std::to_string(&field - run_fields);
}

// The field set to a distinct value in a record whose other fields are their defaults.
RunRecord with_distinct(const RunField& field) {
    RunRecord r;
    std::visit(
        [&](auto member) {
            if constexpr (std::is_member_object_pointer_v<decltype(member)>)
                set_distinct(r.*member);
        },
        field.member);
    return r;
}

// Every field of `expected` that `kept` says a medium keeps is the same in `found`.
template <class Kept>
void expect_same_fields(const RunRecord& expected, const RunRecord& found, bool bits, Kept kept,
                        const std::string& context) {
    for (const RunField& field : run_fields) {
        if (is_computed(field) || !kept(field))
            continue;
        std::visit(
            [&](auto member) {
                if constexpr (std::is_member_object_pointer_v<decltype(member)>) {
                    EXPECT_TRUE(same(expected.*member, found.*member, bits))
                        << name_of(field) << ", " << context;
                }
            },
            field.member);
    }
}

// What runs.csv holds of a record, parsed (without parameter columns).
CsvTable as_runs_csv(const RunRecord& r) {
    std::istringstream text(runs_csv_header({}) + runs_csv_line(r, {}));
    return parse_csv(text, "runs.csv");
}

bool in_runs_csv(const RunField& field) {
    return has_own_column(field);
}

TEST(RunFields, EveryFieldComesBackFromTheStoreBitForBit) {
    const auto stored = [](const RunField& field) { return !is_computed(field); };
    expect_same_fields(RunRecord{}, decode_record(encode_record(RunRecord{}, 0.0)).record, true, stored,
                       "every field at its default");
    for (const RunField& field : run_fields) {
        const RunRecord r = with_distinct(field);
        const std::string bytes = encode_record(r, 1.5);
        expect_same_fields(r, decode_record(bytes).record, true, stored, name_of(field) + " set");
        ByteReader in(bytes, "record");
        EXPECT_EQ(record_succeeded(in), r.ok) << name_of(field) << " set";
    }
}

TEST(RunFields, EveryFieldWithAColumnReadsBackFromRunsCsv) {
    for (const RunField& field : run_fields) {
        if (!in_runs_csv(field) || is_computed(field))
            continue;
        const RunRecord r = with_distinct(field);
        const CsvTable runs = as_runs_csv(r);
        const RunRecord back = read_runs_csv_row(runs, 0, runs_csv_layout(runs));
        const auto shown = [&](const RunField& f) {
            return in_runs_csv(f) && (r.ok || f.shown != Shown::when_ok);
        };
        expect_same_fields(r, back, false, shown, name_of(field) + " set");
    }
}

TEST(RunFields, ARunsCsvWrittenBeforeAFieldExistedReadsItsDefault) {
    for (const RunField& field : run_fields) {
        if (!in_runs_csv(field) || !may_lack_column(field))
            continue;
        CsvTable runs = as_runs_csv(with_distinct(field));
        const std::size_t column = runs.column(field.column);
        runs.header.erase(runs.header.begin() + static_cast<std::ptrdiff_t>(column));
        runs.rows[0].erase(runs.rows[0].begin() + static_cast<std::ptrdiff_t>(column));
        const RunRecord back = read_runs_csv_row(runs, 0, runs_csv_layout(runs));
        expect_same_fields(
            RunRecord{}, back, false, [&](const RunField& f) { return &f == &field; },
            name_of(field) + " without its column");
    }
}

TEST(RunFields, TheParameterColumnsKeepEachParametersValueTruthAndOptimum) {
    RunRecord r;
    r.parameter_names = {"Rs", "Ld"};
    r.best_x = {0.36, 0.0033};
    r.true_parameters = {0.365, 0.00325};
    r.x_opt = {0.364, 0.00326};
    const std::vector<std::string> columns = {"Rs", "Ld", "psi"};
    std::istringstream text(runs_csv_header(columns) + runs_csv_line(r, columns));
    const CsvTable runs = parse_csv(text, "runs.csv");
    const RunsCsvLayout layout = runs_csv_layout(runs);
    EXPECT_EQ(layout.parameters, columns);
    expect_same_fields(
        r, read_runs_csv_row(runs, 0, layout), false, [](const RunField&) { return true; },
        "named parameters");
}

// A field added to the list is stored in a section of its own: a test's list declares one (an
// existing member, since a test cannot add one to RunRecord).
TEST(RunFields, AFieldInASectionComesBackAndIsSkippedByABuildWithoutIt) {
    const RunField added[] = {
        {"evals_to_target", &RunRecord::evaluations_to_target, in_section(first_field_section)}};
    RunRecord r;
    r.evaluations_to_target = 42;
    ByteWriter sections;
    encode_field_sections(sections, r, added);
    ByteReader in(sections.bytes(), "sections");
    const std::uint64_t tag = in.u64();
    EXPECT_EQ(tag, first_field_section);
    const std::string body = in.text();
    EXPECT_TRUE(in.at_end());
    RunRecord back;
    decode_field_section(tag, body, back, added);
    EXPECT_EQ(back.evaluations_to_target, std::optional<std::int64_t>(42));
    RunRecord other;
    decode_field_section(tag + 1, body, other, added); // another build's section: skipped
    EXPECT_FALSE(other.evaluations_to_target.has_value());
    EXPECT_THROW(decode_field_section(tag, body + "x", back, added), std::runtime_error);
    ByteWriter none; // the default needs no section: the record keeps the bytes an older build wrote
    encode_field_sections(none, RunRecord{}, added);
    EXPECT_TRUE(none.bytes().empty());

    // A record carrying the section, read by this build's list (which has no such section).
    std::string record = encode_record(RunRecord{}, 1.0);
    record.resize(record.size() - 8); // before the end tag
    ByteWriter end;
    end.u64(0);
    const RunRecord read = decode_record(record + sections.bytes() + end.bytes()).record;
    EXPECT_FALSE(read.evaluations_to_target.has_value());
}

} // namespace
} // namespace mhb
