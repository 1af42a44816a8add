// Step 3 of a LaTeX table's layout (latex_table.hpp): a table too wide for the page is split into
// parts that repeat the key columns, whole column groups first, each named by its groups; then each
// part is fitted to the page: its wrapped columns share the width the others leave.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "results/latex/latex_layout.hpp"

namespace mhb::latex_detail {

namespace {

double cost(const std::vector<Column>& columns, const std::vector<std::size_t>& which,
            double sep = column_sep) {
    double total = 0.0;
    for (std::size_t k : which)
        total += columns[k].least + 2 * sep;
    return total;
}

// `resize`: a column alone is wider than the page (\resizebox).
Part part_of(std::vector<std::size_t> columns, bool resize) {
    Part part;
    part.columns = std::move(columns);
    part.resize = resize;
    return part;
}

// Columns of one group stay together where they can: the groups in their order, keys left out
// (every part repeats them); a column without a group is a group of its own.
std::vector<std::vector<std::size_t>> column_groups(const std::vector<Column>& columns) {
    std::vector<std::vector<std::size_t>> groups;
    for (std::size_t k = 0; k < columns.size(); ++k) {
        if (columns[k].style.key)
            continue;
        if (groups.empty() || columns[groups.back().back()].style.group != columns[k].style.group ||
            columns[k].style.group.empty())
            groups.emplace_back();
        groups.back().push_back(k);
    }
    return groups;
}

// A last part holding one column beside the keys (in the comparison, one algorithm: a float of its
// own) takes columns from the part before while both still fit and that one keeps more.
void balance_last_part(const std::vector<Column>& columns, std::size_t keys, std::vector<Part>& parts) {
    if (parts.size() < 2)
        return;
    Part& last = parts.back();
    Part& before = parts[parts.size() - 2];
    // Only columns of no group move (a group stays whole): the comparison's algorithms.
    const auto loose = [&](const Part& part) { return columns[part.columns.back()].style.group.empty(); };
    while (last.columns.size() - keys < 2 && before.columns.size() - keys > 2 && loose(last) &&
           loose(before)) {
        std::vector<std::size_t> moved = last.columns;
        moved.insert(moved.begin() + static_cast<std::ptrdiff_t>(keys), before.columns.back());
        if (cost(columns, moved) > usable_width)
            return;
        last.columns = std::move(moved);
        before.columns.pop_back();
    }
}

// The key columns and as many groups as fit, part by part; a group too wide on its own goes column
// by column.
std::vector<Part> parts_by_groups(const std::vector<Column>& columns) {
    std::vector<std::size_t> keys;
    for (std::size_t k = 0; k < columns.size(); ++k)
        if (columns[k].style.key)
            keys.push_back(k);
    std::vector<Part> parts;
    std::vector<std::size_t> current;
    const auto with = [&](const std::vector<std::size_t>& more) {
        std::vector<std::size_t> all = keys;
        all.insert(all.end(), current.begin(), current.end());
        all.insert(all.end(), more.begin(), more.end());
        return all;
    };
    const auto close = [&] {
        if (current.empty())
            return;
        std::vector<std::size_t> all = with({}); // the keys first, then the part's own columns
        parts.push_back(part_of(all, cost(columns, all) > usable_width));
        current.clear();
    };
    for (const auto& group : column_groups(columns)) {
        if (cost(columns, with(group)) <= usable_width) {
            current.insert(current.end(), group.begin(), group.end());
            continue;
        }
        close();
        if (cost(columns, with(group)) <= usable_width) {
            current = group;
            continue;
        }
        for (std::size_t k : group) { // a group too wide on its own: column by column
            if (!current.empty() && cost(columns, with({k})) > usable_width)
                close();
            current.push_back(k);
        }
    }
    close();
    balance_last_part(columns, keys.size(), parts);
    return parts;
}

// A part's name, for its caption: the groups of its columns other than the keys.
std::string part_name(const std::vector<Column>& columns, const Part& part) {
    std::vector<std::string> names;
    for (std::size_t k : part.columns) {
        const std::string& g = columns[k].style.group;
        if (!columns[k].style.key && !g.empty() && std::find(names.begin(), names.end(), g) == names.end())
            names.push_back(g);
    }
    return join(names, ", ");
}

// Wrapped columns share what the others leave, up to their width on one line.
void fit_to_page(const std::vector<Column>& columns, double sep, Part& part) {
    double fixed = 0.0;
    double slack = 0.0;
    for (std::size_t k : part.columns) {
        fixed += columns[k].least + 2 * sep;
        if (columns[k].wrap)
            slack += columns[k].natural - columns[k].least;
    }
    const double spare = std::max(0.0, usable_width - fixed);
    part.wrap_width.assign(columns.size(), 0.0);
    double width = 0.0;
    for (std::size_t k : part.columns) {
        const Column& column = columns[k];
        if (column.wrap) {
            const double share = slack > 0.0 ? std::min(1.0, spare / slack) : 0.0;
            part.wrap_width[k] = std::ceil(column.least + share * (column.natural - column.least));
            part.spec += ">{\\raggedright\\arraybackslash}p{" +
                         std::to_string(static_cast<int>(part.wrap_width[k])) + "pt}";
            width += part.wrap_width[k];
        } else {
            part.spec += column.numeric ? "r" : "l";
            width += column.natural;
        }
        width += 2 * sep;
    }
    part.wide = width > ieee_column;
}

} // namespace

// 3. The parts: one table if it fits, else the key columns and as many groups as fit.
void split_into_parts(TableLayout& layout) {
    const std::vector<Column>& columns = layout.columns;
    std::vector<std::size_t> everything(columns.size());
    std::iota(everything.begin(), everything.end(), 0);
    layout.sep = column_sep;
    if (cost(columns, everything) > usable_width && cost(columns, everything, tight_sep) <= usable_width)
        layout.sep = tight_sep;
    if (cost(columns, everything, layout.sep) <= usable_width) {
        layout.parts.push_back(part_of(everything, false));
    } else {
        layout.parts = parts_by_groups(columns);
        if (layout.parts.empty())
            layout.parts.push_back(part_of(everything, true));
        for (auto& part : layout.parts)
            part.name = part_name(columns, part);
    }
    for (auto& part : layout.parts)
        fit_to_page(columns, layout.sep, part);
}

bool footer_row_shown(const TableLayout& layout, const Part& part, const std::vector<Cell>& row) {
    return std::any_of(part.columns.begin(), part.columns.end(),
                       [&](std::size_t k) { return !layout.columns[k].style.key && !row[k].empty; });
}

} // namespace mhb::latex_detail
