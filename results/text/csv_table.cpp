#include "results/text/csv_table.hpp"

#include "results/store/csv.hpp" // CSV as the store writes it, for every room

namespace mhb {

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

} // namespace mhb
