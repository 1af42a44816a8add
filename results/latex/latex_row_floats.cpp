// How a part of a LaTeX table (latex_column_parts.cpp) splits by rows into floats that fit a page
// (latex_table.hpp): the height of what it holds, estimated from heights pdflatex measured, and the
// breaks, as few floats as fit, as evenly filled as the runs of rows under one heading allow.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "results/latex/latex_layout.hpp"
#include "results/latex/latex_text.hpp"

namespace mhb::latex_detail {

namespace {

// Heights, measured with pdflatex (tests/latex/ checks real reports against the page). The text
// height of a one-column article, 10 pt, default geometry, is the smallest of the targets (IEEEtran
// conference 672 pt, elsarticle 5p 682 pt); 96 % of it is used, as of the width.
constexpr double page_height = 550.0;
constexpr double usable_height = 0.96 * page_height;
constexpr double row_height = 9.8;   // a \footnotesize row (9.75 pt; 9.79 with exponents and \boldmath)
constexpr double rules_height = 8.6; // \toprule, \midrule and \bottomrule with their spacing
constexpr double heading_height = row_height + 4.5; // a heading line and the \addlinespace above it
constexpr double footer_rule = 7.0;                 // the \midrule above the w/t/l rows
constexpr double caption_base = 23.0;               // IEEEtran's "TABLE I" line and the skips (article: 7 pt)
constexpr double caption_line = 12.0;  // a line of caption (\normalsize in article; 9 pt in IEEEtran)
constexpr double caption_scale = 1.25; // \normalsize against the \footnotesize widths are estimated at
constexpr double notes_skip = 6.0;     // \medskip above the notes
constexpr double notes_line = 9.5;     // a line of notes (\footnotesize)
constexpr double ragged = 1.1;         // ragged-right lines end short of the width

// The rows of a table part and the room a float has for them, in pt.
struct Heights {
    std::vector<double> rows;      // each body row: a line, two with the spread below, more if wrapped
    std::vector<bool> group_start; // a heading line goes above the row (a run of rows begins)
    double heading = 0.0;          // a heading line, when the table has headings
    double footer = 0.0;           // the w/t/l rows under the body, in the last float
    double first_room = 0.0;       // a float with the caption, the header and the notes
    double later_room = 0.0;       // a continued float: the caption and header, no notes
};

// Rows [first, second) of each float, each fitting its room at `scale`: runs of rows stay
// together where the float would still be at least half full, a float's first row is headed (the
// heading repeats when a run continues), a heading never ends a float (it goes with its first
// row), and the footer goes with the last row.
std::vector<RowRange> pack_rows(const Heights& heights, double scale) {
    const std::size_t n = heights.rows.size();
    std::vector<RowRange> out;
    for (std::size_t start = 0; start < n;) {
        const double room = scale * (out.empty() ? heights.first_room : heights.later_room);
        double used = 0.0;
        double used_at_boundary = 0.0;
        std::size_t end = start;
        std::size_t boundary = start; // the last end at which a run of rows ends
        for (std::size_t r = start; r < n; ++r) {
            double h = heights.rows[r] + (r == start || heights.group_start[r] ? heights.heading : 0.0);
            if (r + 1 == n)
                h += heights.footer;
            if (r > start && used + h > room)
                break;
            used += h;
            end = r + 1;
            if (end == n || heights.group_start[end]) {
                boundary = end;
                used_at_boundary = used;
            }
        }
        if (end < n && boundary > start) {
            std::size_t run_begin = end - 1; // the run the float would end inside
            while (run_begin > start && !heights.group_start[run_begin])
                --run_begin;
            // A run cut short leaves at least two rows above the cut.
            if (used_at_boundary >= 0.5 * room || end - run_begin < 2)
                end = boundary;
        }
        out.emplace_back(start, end);
        start = end;
    }
    if (out.empty())
        out.emplace_back(0, 0);
    return out;
}

// As few floats as fit, as evenly filled as they can be: the smallest room that needs no more
// floats than the full room does.
std::vector<RowRange> split_rows(const Heights& heights) {
    auto best = pack_rows(heights, 1.0);
    if (best.size() < 2)
        return best;
    double low = 0.0;
    double high = 1.0;
    for (int i = 0; i < 30; ++i) {
        const double mid = (low + high) / 2;
        if (auto chunks = pack_rows(heights, mid); chunks.size() <= best.size()) {
            high = mid;
            best = std::move(chunks);
        } else {
            low = mid;
        }
    }
    return best;
}

// The height of each body row of the part, where runs of rows begin, and the heading's and footer's
// heights.
Heights row_heights(const Table& table, const TableLayout& layout, const Part& part) {
    Heights heights;
    const auto& heading = layout.heading;
    for (std::size_t r = 0; r < layout.body.size(); ++r) {
        std::size_t row_lines = 1;
        for (std::size_t k : part.columns) {
            const Cell& cell = layout.body[r][k];
            if (!cell.below.empty())
                row_lines = std::max<std::size_t>(row_lines, 2);
            if (layout.columns[k].wrap && part.wrap_width[k] > 0.0)
                row_lines =
                    std::max(row_lines, static_cast<std::size_t>(std::ceil(cell.width / part.wrap_width[k])));
        }
        heights.rows.push_back(static_cast<double>(row_lines) * row_height);
        heights.group_start.push_back(
            heading && (r == 0 || table.rows[r][*heading].text != table.rows[r - 1][*heading].text));
    }
    heights.heading = heading ? heading_height : 0.0;
    const auto footer_rows = std::count_if(layout.footer.begin(), layout.footer.end(), [&](const auto& row) {
        return footer_row_shown(layout, part, row);
    });
    if (footer_rows > 0) // a footer's label may head its row (latex_table.cpp): counted as a heading
        heights.footer =
            footer_rule + static_cast<double>(footer_rows) *
                              (layout.footer_label_kept || heading ? row_height : heading_height);
    return heights;
}

// The lines of the part's column header: its tallest header.
std::size_t header_lines_of(const TableLayout& layout, const Part& part) {
    std::size_t head_lines = 1;
    for (std::size_t k : part.columns) {
        const Column& column = layout.columns[k];
        std::size_t lines = column.header_lines.size();
        if (column.wrap && part.wrap_width[k] > 0.0)
            lines = static_cast<std::size_t>(
                std::ceil(latex_text_width(header_cell(column)) / part.wrap_width[k]));
        head_lines = std::max(head_lines, lines);
    }
    return head_lines;
}

} // namespace

std::vector<RowRange> row_floats(const Table& table, const TableLayout& layout, const Part& part,
                                 const std::string& caption, const std::string& notes) {
    Heights heights = row_heights(table, layout, part);
    const double head_lines = static_cast<double>(header_lines_of(layout, part));
    const double float_width = part.wide ? page_width : ieee_column; // the narrowest text it wraps in
    const auto lines_of = [](double text_width, double line) {
        return std::max(1.0, std::ceil(text_width / line));
    };
    const auto frame = [&](const std::string& text) { // caption, header and rules
        return caption_base + caption_line * lines_of(caption_scale * latex_text_width(text), float_width) +
               rules_height + head_lines * row_height;
    };
    const double notes_room =
        notes.empty() ? 0.0
                      : notes_skip + notes_line * lines_of(ragged * latex_text_width(notes), float_width);
    heights.first_room = usable_height - frame(caption) - notes_room;
    heights.later_room = usable_height - frame(caption + " (continued)");
    return split_rows(heights);
}

} // namespace mhb::latex_detail
