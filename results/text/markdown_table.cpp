#include "results/text/markdown_table.hpp"

namespace mhb {

namespace {

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

} // namespace mhb
