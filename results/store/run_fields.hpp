// The fields of a run's record (RunRecord), declared once: each field's column in runs.csv, its
// place in store.bin's record and how runs.csv shows it. The record codec (run_field_codec.cpp),
// the runs.csv writer and its reader (runs_csv.cpp) iterate this list instead of naming fields,
// and check it at compile time. A new field is one line here, where its column goes in runs.csv
// (not between best_x and message: older builds take what is there for parameter columns), stored
// in a section of its own (`in_section(k)`, k the next free tag), plus its member in
// run_record.hpp and the code that computes it; the tests that iterate the list
// (tests/unit/results/run_fields_test.cpp) cover it without being edited.
//
// Not in the list, each with code of its own:
// - the curve, the checkpoints and the improvement trace, nested parts with files of their own
//   (curves.csv, checkpoints.csv, trajectories.csv, improvements.csv): record_codec.cpp stores them
//   after the fields, rendered_lines.cpp writes them and study_reader.cpp reads them;
// - the parameter columns of runs.csv (P, P_true, P_opt and P_err_pct for each named parameter of
//   the study): a layout over four fields (parameter_names, best_x, true_parameters, x_opt) and the
//   study's columns, which runs_csv.cpp writes and reads by hand where parameter_names stands here;
// - wall_seconds, not part of a RunRecord since it differs between two runs of one study: the
//   codec keeps it after the checkpoints, and timings.csv shows it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "results/store/run_record.hpp"

namespace mhb {

// A field as the member it is. Its type decides how it is stored and how runs.csv writes it:
//   std::int64_t, std::uint64_t   8 bytes; a decimal integer
//   bool                          8 bytes, 1 or 0; two words (Shown::ok_or_failed)
//   double                        its 8 bytes, bit for bit; csv_number (the shortest exact text)
//   std::string                   length and bytes; csv_field (quoted when needed)
//   std::optional<double>, std::optional<std::int64_t>
//                                 8 bytes, 1 or 0, then the value (0 when unset); empty when unset
//   std::vector<double>           count, then the values; the numbers separated by spaces
//   std::vector<std::string>      count, then the texts; only as the parameter names
//   a const member function       computed for runs.csv only: neither stored nor read back
using RunFieldMember =
    std::variant<std::int64_t RunRecord::*, std::uint64_t RunRecord::*, bool RunRecord::*,
                 double RunRecord::*, std::string RunRecord::*, std::optional<double> RunRecord::*,
                 std::optional<std::int64_t> RunRecord::*, std::vector<double> RunRecord::*,
                 std::vector<std::string> RunRecord::*, std::optional<double> (RunRecord::*)() const>;

// Where a field is in store.bin's record (record_codec.hpp). Format 3 fixed the record's first
// fields and their order, its core; a field added since is a section of its own, written when its
// value is not the default: records without it (stored before it existed, or holding the default)
// read it as the member's default, and older mhbench builds skip it.
struct StorePlace {
    int core = -1;             // position among the core fields, from 0
    std::uint64_t section = 0; // the section's tag: 2, 3, ... (1 is the improvement trace)
};
constexpr StorePlace in_core(int position) {
    return {position, 0};
}
constexpr StorePlace in_section(std::uint64_t tag) {
    return {-1, tag};
}
inline constexpr StorePlace not_stored{};

// How runs.csv shows a field.
enum class Shown {
    as_is,         // a column, the value written as its type says
    when_ok,       // the same, but empty for a failed run, and not read back for one
    ok_or_failed,  // a bool as the words ok and failed
    as_parameters, // the parameter columns, for the study's parameter names (see above)
    in_parameters, // no column of its own: shown in the parameter columns
};

// Whether every runs.csv has the field's column. A field added after studies were written is
// missing from their runs.csv, which then reads as the member's default: so is every field in a
// section, and so is budget, which came after runs.csv.
enum class Column { in_every_runs_csv, added_later };

struct RunField {
    const char* column; // its name in runs.csv ("" when it has no column of its own)
    RunFieldMember member;
    StorePlace stored;
    Shown shown = Shown::as_is;
    Column since = Column::in_every_runs_csv;
};

// In runs.csv's column order.
inline constexpr RunField run_fields[] = {
    {"run_id", &RunRecord::run_id, in_core(0)},
    {"algorithm", &RunRecord::algorithm, in_core(1)},
    {"problem", &RunRecord::problem, in_core(2)},
    {"budget", &RunRecord::budget, in_core(3), Shown::as_is, Column::added_later},
    {"run", &RunRecord::run_index, in_core(4)},
    {"seed", &RunRecord::seed, in_core(5)},
    {"status", &RunRecord::ok, in_core(6), Shown::ok_or_failed},
    {"evaluations", &RunRecord::evaluations, in_core(11)},
    {"iterations", &RunRecord::iterations, in_core(12)},
    {"best_f", &RunRecord::best_f, in_core(8), Shown::when_ok},
    {"f_opt", &RunRecord::f_opt, in_core(9)},
    {"error", &RunRecord::error, not_stored},
    {"evals_to_target", &RunRecord::evaluations_to_target, in_core(13)},
    {"best_x", &RunRecord::best_x, in_core(14)},
    {"", &RunRecord::parameter_names, in_core(15), Shown::as_parameters},
    {"", &RunRecord::true_parameters, in_core(16), Shown::in_parameters},
    {"", &RunRecord::x_opt, in_core(10), Shown::in_parameters},
    {"message", &RunRecord::message, in_core(7)},
};

// Whether a runs.csv may lack the field's column (see Column).
constexpr bool may_lack_column(const RunField& field) {
    return field.since == Column::added_later || field.stored.section != 0;
}

// Whether the field is computed rather than kept (a member function).
constexpr bool is_computed(const RunField& field) {
    return std::holds_alternative<std::optional<double> (RunRecord::*)() const>(field.member);
}

// Whether the field has a column of its own in runs.csv.
constexpr bool has_own_column(const RunField& field) {
    return field.shown != Shown::as_parameters && field.shown != Shown::in_parameters;
}

} // namespace mhb
