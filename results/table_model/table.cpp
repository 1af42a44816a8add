#include "results/table_model/table.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "results/store/csv.hpp"
#include "results/table_model/number_format.hpp"

namespace mhb {

void Table::add_row(std::vector<TableCell> row) {
    if (row.size() != header.size())
        throw std::logic_error("table " + id + ": a row has " + std::to_string(row.size()) + " cells for " +
                               std::to_string(header.size()) + " columns");
    rows.push_back(std::move(row));
}

void Table::add_footer(std::vector<TableCell> row) {
    if (row.size() != header.size())
        throw std::logic_error("table " + id + ": a footer row has " + std::to_string(row.size()) +
                               " cells for " + std::to_string(header.size()) + " columns");
    footer.push_back(std::move(row));
}

LatexColumn& Table::latex_column(std::size_t column) {
    if (column >= header.size())
        throw std::logic_error("table " + id + ": no column " + std::to_string(column));
    if (latex.size() != header.size()) {
        latex.assign(header.size(), LatexColumn{});
        latex.front().key = true;
    }
    return latex[column];
}

namespace {

// A number as one field of a composite CSV value; NaN (undefined) is empty, as a cell of it is.
std::string csv_part(double value) {
    return std::isnan(value) ? std::string() : csv_number(value);
}

std::string spread_text(const std::string& spread, SpreadStyle style) {
    return style == SpreadStyle::parentheses ? " (" + spread + ")" : " / " + spread + "%";
}

} // namespace

void format_columns(Table& table) {
    const std::vector<ColumnFormats> formats = column_formats(table);
    for (auto* rows : {&table.rows, &table.footer})
        for (auto& row : *rows)
            for (std::size_t c = 0; c < row.size() && c < formats.size(); ++c) {
                TableCell& cell = row[c];
                if (!cell.number)
                    continue;
                cell.text = plain_number(*cell.number, formats[c].numbers.at(cell.group));
                if (cell.spread)
                    cell.text += spread_text(plain_number(*cell.spread, formats[c].spreads.at(cell.group)),
                                             cell.spread_style);
                if (!cell.marker.empty())
                    cell.text += " " + cell.marker;
            }
}

std::string format_number(double value, int significant) {
    if (std::isnan(value))
        return undefined_text;
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
    return buffer;
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
    std::string out;
    for (const auto& item : items)
        out += (out.empty() ? "" : separator) + item;
    return out;
}

std::string format_fixed(double value, int decimals) {
    if (!std::isfinite(value))
        return format_number(value);
    char buffer[400];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

TableCell number_cell(double value, int significant) {
    TableCell cell;
    cell.text = format_number(value, significant);
    cell.value = std::isnan(value) ? "" : csv_number(value); // an undefined value: an empty CSV field
    cell.number = value;
    cell.digits = {significant, -1};
    return cell;
}

TableCell fixed_cell(double value, int decimals) {
    TableCell cell = number_cell(value);
    cell.text = format_fixed(value, decimals);
    cell.digits = {1, decimals};
    return cell;
}

TableCell spread_cell(double value, double spread, const std::string& marker, Digits value_digits,
                      Digits spread_digits) {
    TableCell cell;
    cell.number = value;
    cell.digits = value_digits;
    cell.spread = spread;
    cell.spread_digits = spread_digits;
    cell.marker = marker;
    cell.text = format_number(value, value_digits.significant) + " (" +
                format_number(spread, spread_digits.significant) + ")" + (marker.empty() ? "" : " " + marker);
    cell.value = csv_part(value) + " (" + csv_part(spread) + ")" + (marker.empty() ? "" : " " + marker);
    return cell;
}

TableCell text_cell(std::string text) {
    TableCell cell;
    cell.text = std::move(text);
    return cell;
}

} // namespace mhb
