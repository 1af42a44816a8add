// runs.csv from the fields of run_fields.hpp (see runs_csv.hpp).
#include "results/store/runs_csv.hpp"

#include <charconv>
#include <cstddef>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <variant>

#include "results/store/run_fields.hpp"

namespace mhb {
namespace {

using ParameterNames = std::vector<std::string> RunRecord::*;

// The fields whose columns are on either side of the parameter columns (best_x and message), by
// their index in run_fields: the reader finds the parameter columns between them.
struct Neighbours {
    std::size_t before = 0;
    std::size_t after = 0;
};
constexpr Neighbours parameter_neighbours = [] {
    std::size_t names = 0;
    while (run_fields[names].shown != Shown::as_parameters)
        ++names;
    Neighbours n{names, names + 1};
    while (n.before > 0 && !has_own_column(run_fields[n.before]))
        --n.before;
    while (n.after + 1 < std::size(run_fields) && !has_own_column(run_fields[n.after]))
        ++n.after;
    return n;
}();

// What the writer and the reader below take for granted of run_fields.
consteval bool runs_csv_can_show_each() {
    std::size_t parameter_blocks = 0;
    bool ok_read = false;
    for (const RunField& field : run_fields) {
        const bool names = std::holds_alternative<ParameterNames>(field.member);
        const bool numbers = std::holds_alternative<std::vector<double> RunRecord::*>(field.member);
        const bool flag = std::holds_alternative<bool RunRecord::*>(field.member);
        if (names != (field.shown == Shown::as_parameters) ||
            (field.shown == Shown::in_parameters && !numbers) ||
            flag != (field.shown == Shown::ok_or_failed) || (field.shown == Shown::when_ok && !ok_read) ||
            has_own_column(field) == std::string_view(field.column).empty())
            return false;
        parameter_blocks += names ? 1 : 0;
        ok_read = ok_read || (flag && std::get<bool RunRecord::*>(field.member) == &RunRecord::ok);
        for (const RunField& other : run_fields)
            if (&other != &field && has_own_column(field) &&
                std::string_view(other.column) == std::string_view(field.column))
                return false;
    }
    // Builds from before a field was added find the parameter columns between the same two.
    const RunField& before = run_fields[parameter_neighbours.before];
    const RunField& after = run_fields[parameter_neighbours.after];
    return parameter_blocks == 1 && has_own_column(run_fields[0]) && has_own_column(before) &&
           has_own_column(after) && !may_lack_column(before) && !may_lack_column(after);
}
static_assert(runs_csv_can_show_each(),
              "run_fields: each field with a column of its own and a name no other has, the first among "
              "them; one list of parameter names (Shown::as_parameters), the numbers shown with them "
              "(Shown::in_parameters), with a column in every runs.csv on either side; a bool only "
              "as the words ok and failed (after status, the fields shown when ok)");

constexpr const char* ok_word = "ok";
constexpr const char* failed_word = "failed";

std::string join_numbers(const std::vector<double>& values) {
    std::string out;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0)
            out += ' ';
        out += csv_number(values[i]);
    }
    return out;
}

// A cell's text, by the field's type (run_fields.hpp).
std::string cell_text(std::int64_t value) {
    return std::to_string(value);
}
std::string cell_text(std::uint64_t value) {
    return std::to_string(value);
}
std::string cell_text(bool value) {
    return value ? ok_word : failed_word;
}
std::string cell_text(double value) {
    return csv_number(value);
}
std::string cell_text(const std::string& value) {
    return csv_field(value);
}
std::string cell_text(const std::optional<double>& value) {
    return csv_optional(value);
}
std::string cell_text(const std::optional<std::int64_t>& value) {
    return value ? std::to_string(*value) : "";
}
std::string cell_text(const std::vector<double>& values) {
    return join_numbers(values);
}

std::string cell(const RunRecord& r, const RunField& field) {
    return std::visit(
        [&](auto member) -> std::string {
            if constexpr (std::is_member_function_pointer_v<decltype(member)>)
                return cell_text((r.*member)());
            else if constexpr (std::is_same_v<decltype(member), ParameterNames>)
                throw std::logic_error("runs.csv: the parameter names have no cell of their own");
            else
                return cell_text(r.*member);
        },
        field.member);
}

// For each of the study's parameters: the run's value, the true value, the value at the known
// optimum and the error in % of the true value, each empty where the run has none.
std::string parameter_cells(const RunRecord& r, const std::vector<std::string>& columns) {
    std::string cells;
    for (const auto& column : columns) {
        std::string value;
        std::string truth;
        std::string optimum;
        std::string error;
        for (std::size_t k = 0; k < r.parameter_names.size(); ++k) {
            if (r.parameter_names[k] != column || k >= r.best_x.size())
                continue;
            value = csv_number(r.best_x[k]);
            if (k < r.x_opt.size())
                optimum = csv_number(r.x_opt[k]);
            if (k < r.true_parameters.size()) {
                truth = csv_number(r.true_parameters[k]);
                if (r.true_parameters[k] != 0.0)
                    error = csv_number(100.0 * (r.best_x[k] - r.true_parameters[k]) / r.true_parameters[k]);
            }
        }
        cells += ',' + value + ',' + truth + ',' + optimum + ',' + error;
    }
    return cells;
}

std::runtime_error bad_row(const CsvTable& runs, std::size_t row, const std::string& what) {
    return std::runtime_error(runs.path.string() + ", line " + std::to_string(runs.line_numbers[row]) + what);
}

std::vector<double> split_numbers(const CsvTable& t, std::size_t row, std::size_t column) {
    std::vector<double> values;
    const std::string& text = t.rows[row][column];
    std::size_t i = 0;
    while (i < text.size()) {
        const auto j = std::min(text.find(' ', i), text.size());
        double v = 0;
        const auto [ptr, ec] = std::from_chars(text.data() + i, text.data() + j, v);
        if (ec != std::errc() || ptr != text.data() + j)
            throw bad_row(t, row, ", column '" + t.header[column] + "': not a list of numbers");
        values.push_back(v);
        i = j + 1;
    }
    return values;
}

// A cell read back into a field's value, by its type: what cell_text wrote, or an error.
void read_cell(const CsvTable& runs, std::size_t row, std::size_t column, std::int64_t& value) {
    value = runs.integer(row, column);
}
void read_cell(const CsvTable& runs, std::size_t row, std::size_t column, std::uint64_t& value) {
    const std::string& text = runs.rows[row][column];
    if (std::from_chars(text.data(), text.data() + text.size(), value).ec != std::errc())
        throw bad_row(runs, row, ", column '" + runs.header[column] + "': not an unsigned integer");
}
void read_cell(const CsvTable& runs, std::size_t row, std::size_t column, bool& value) {
    const std::string& text = runs.rows[row][column];
    if (text != ok_word && text != failed_word)
        throw bad_row(runs, row,
                      ", column '" + runs.header[column] + "': '" + text + "' is not " + ok_word + " or " +
                          failed_word);
    value = text == ok_word;
}
void read_cell(const CsvTable& runs, std::size_t row, std::size_t column, double& value) {
    value = runs.number(row, column);
}
void read_cell(const CsvTable& runs, std::size_t row, std::size_t column, std::string& value) {
    value = runs.rows[row][column];
}
void read_cell(const CsvTable& runs, std::size_t row, std::size_t column, std::optional<double>& value) {
    value = runs.optional_number(row, column);
}
// Written as an integer; read as one, so that no text (1e300, nan) becomes a cast out of range.
void read_cell(const CsvTable& runs, std::size_t row, std::size_t column,
               std::optional<std::int64_t>& value) {
    if (runs.rows[row][column].empty())
        value.reset();
    else
        value = runs.integer(row, column);
}
void read_cell(const CsvTable& runs, std::size_t row, std::size_t column, std::vector<double>& values) {
    values = split_numbers(runs, row, column);
}

void read_field(const CsvTable& runs, std::size_t row, std::size_t column, const RunField& field,
                RunRecord& r) {
    std::visit(
        [&](auto member) {
            if constexpr (std::is_member_object_pointer_v<decltype(member)> &&
                          !std::is_same_v<decltype(member), ParameterNames>)
                read_cell(runs, row, column, r.*member);
        },
        field.member);
}

// The named parameters a run has values for, with their true values and optima when it has them
// for all.
void read_parameters(const CsvTable& runs, std::size_t row, const RunsCsvLayout& layout, RunRecord& r) {
    bool all_truths = true;
    bool all_optima = true;
    for (std::size_t c = layout.first; c < layout.end; c += layout.per_parameter) {
        if (runs.rows[row][c].empty())
            continue;
        r.parameter_names.push_back(runs.header[c]);
        const auto truth = runs.optional_number(row, c + 1);
        all_truths = all_truths && truth.has_value();
        r.true_parameters.push_back(truth.value_or(0.0));
        const auto optimum = runs.optional_number(row, c + 2);
        all_optima = all_optima && optimum.has_value();
        r.x_opt.push_back(optimum.value_or(0.0));
    }
    if (!all_truths)
        r.true_parameters.clear();
    if (!all_optima)
        r.x_opt.clear();
}

// The column of `field` in `runs`, unless it is one that a runs.csv written before it lacks.
std::optional<std::size_t> column_of(const CsvTable& runs, const RunField& field) {
    if (may_lack_column(field) && !runs.has_column(field.column))
        return std::nullopt;
    return runs.column(field.column);
}

} // namespace

std::string runs_csv_header(const std::vector<std::string>& parameter_columns) {
    std::string header;
    for (const RunField& field : run_fields) {
        if (field.shown == Shown::as_parameters) {
            for (const auto& p : parameter_columns)
                header += "," + p + "," + p + "_true," + p + "_opt," + p + "_err_pct";
        } else if (has_own_column(field)) {
            if (&field != run_fields)
                header += ',';
            header += field.column;
        }
    }
    return header + '\n';
}

std::string runs_csv_line(const RunRecord& r, const std::vector<std::string>& parameter_columns) {
    std::string line;
    for (const RunField& field : run_fields) {
        if (field.shown == Shown::as_parameters) {
            line += parameter_cells(r, parameter_columns);
        } else if (has_own_column(field)) {
            if (&field != run_fields)
                line += ',';
            if (field.shown != Shown::when_ok || r.ok)
                line += cell(r, field);
        }
    }
    return line + '\n';
}

RunsCsvLayout runs_csv_layout(const CsvTable& runs) {
    RunsCsvLayout layout{runs.column(run_fields[parameter_neighbours.before].column) + 1,
                         runs.column(run_fields[parameter_neighbours.after].column),
                         {}};
    if (layout.end < layout.first || (layout.end - layout.first) % layout.per_parameter != 0)
        throw std::runtime_error(runs.path.string() + ": parameter columns are malformed");
    for (std::size_t c = layout.first; c < layout.end; c += layout.per_parameter)
        layout.parameters.push_back(runs.header[c]);
    return layout;
}

RunRecord read_runs_csv_row(const CsvTable& runs, std::size_t row, const RunsCsvLayout& layout) {
    RunRecord r;
    for (const RunField& field : run_fields) {
        if (field.shown == Shown::as_parameters)
            read_parameters(runs, row, layout, r);
        if (!has_own_column(field) || is_computed(field) || (field.shown == Shown::when_ok && !r.ok))
            continue;
        if (const auto column = column_of(runs, field))
            read_field(runs, row, *column, field, r);
    }
    return r;
}

} // namespace mhb
