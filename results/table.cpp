#include "results/table.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "results/csv.hpp"
#include "results/latex_numbers.hpp"

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

// Markdown cells may not hold '|' (it would split the cell).
std::string markdown_text(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '|')
            out += "\\|";
        else
            out += c;
    }
    return out;
}

bool numeric_column(const Table& table, std::size_t column) {
    for (const auto& row : table.rows)
        if (row[column].number)
            return true;
    return false;
}

void markdown_row(std::string& out, const std::vector<TableCell>& row) {
    out += "|";
    for (const auto& cell : row) {
        const std::string text = markdown_text(cell.text);
        out += ' ';
        if (cell.bold && !text.empty())
            out.append("**").append(text).append("**");
        else
            out += text;
        out += " |";
    }
    out += "\n";
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

std::string render_markdown(const Table& table) {
    std::string out = "### " + table.title + "\n\n|";
    for (const auto& h : table.header)
        out.append(" ").append(markdown_text(h)).append(" |");
    out += "\n|";
    // Text columns left, number columns right: numbers line up on their last digit.
    for (std::size_t c = 0; c < table.header.size(); ++c)
        out += numeric_column(table, c) ? " ---: |" : " :--- |";
    out += "\n";
    for (const auto& row : table.rows)
        markdown_row(out, row);
    for (const auto& row : table.footer)
        markdown_row(out, row);
    if (!table.caption.empty())
        out += "\n" + table.caption + "\n";
    return out;
}

std::string render_csv(const Table& table) {
    std::string out;
    for (std::size_t c = 0; c < table.header.size(); ++c)
        out.append(c == 0 ? "" : ",").append(csv_field(table.header[c]));
    out += "\n";
    for (const auto& row : table.rows) {
        for (std::size_t c = 0; c < row.size(); ++c)
            out.append(c == 0 ? "" : ",")
                .append(row[c].value.empty() && row[c].text == undefined_text
                            ? std::string()
                            : csv_field(row[c].value.empty() ? row[c].text : row[c].value));
        out += "\n";
    }
    return out;
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
