#include "results/analysis/dimension_budget.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {
namespace {

const char* const allowed_forms = "a count N, N*dim (N x the problem's dimension) or dimD:N+dimD:N+... (N at "
                                  "each dimension D listed), e.g. 10000*dim or dim10:200000+dim20:1000000";

// A whole positive integral number, 1e4 allowed, within [1, max].
bool parse_count(std::string_view text, std::int64_t max, std::int64_t& out) {
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size())
        return false;
    if (!(value >= 1.0 && value <= static_cast<double>(max)) || value != std::floor(value))
        return false;
    out = static_cast<std::int64_t>(value);
    return true;
}

} // namespace

bool DimensionEvaluations::written_in(std::string_view value) {
    // Not '+': a plain count may be written +5 or 1e+5.
    return value.find_first_of("*:") != std::string_view::npos || value.find("dim") != std::string_view::npos;
}

DimensionEvaluations DimensionEvaluations::parse(std::string_view value) {
    const std::string shown(value.substr(0, 60));
    const auto fail = [&](const std::string& why) {
        throw std::invalid_argument("budget: parameter 'evaluations' = " + shown + " " + why + "; write " +
                                    allowed_forms);
    };
    // Appended rather than "..." + to_string(...) + "]": GCC 12 warns falsely (-Warray-bounds) on that.
    std::string count_rule = "is not an integer in [1, ";
    count_rule.append(std::to_string(max_budget_evaluations)).append("]");
    DimensionEvaluations out;
    if (const auto star = value.find('*'); star != std::string_view::npos) {
        // N*dim, or dim*N.
        std::string_view count = value.substr(0, star);
        std::string_view factor = value.substr(star + 1);
        if (count == "dim")
            std::swap(count, factor);
        if (factor != "dim")
            fail("multiplies by '" + std::string(factor.substr(0, 20)) + "', not by dim");
        if (!parse_count(count, max_budget_evaluations, out.per_dimension))
            fail("has a factor '" + std::string(count.substr(0, 20)) + "' that " + count_rule);
        return out;
    }
    std::size_t start = 0;
    while (start <= value.size()) {
        const auto end = std::min(value.find('+', start), value.size());
        const std::string_view item = value.substr(start, end - start);
        const auto colon = item.find(':');
        if (item.substr(0, 3) != "dim" || colon == std::string_view::npos)
            fail("has an item '" + std::string(item.substr(0, 20)) + "' that is not dimD:N");
        std::int64_t dimension = 0;
        std::int64_t evaluations = 0;
        if (!parse_count(item.substr(3, colon - 3), 1000000, dimension))
            fail("has a dimension '" + std::string(item.substr(3, std::min<std::size_t>(colon - 3, 20))) +
                 "' that is not an integer in [1, 1000000]");
        if (!parse_count(item.substr(colon + 1), max_budget_evaluations, evaluations))
            fail("has a count '" + std::string(item.substr(colon + 1, 20)) + "' that " + count_rule);
        for (const auto& [d, e] : out.listed)
            if (d == dimension)
                fail("lists dimension " + std::to_string(dimension) + " twice");
        out.listed.emplace_back(dimension, evaluations);
        start = end + 1;
    }
    std::sort(out.listed.begin(), out.listed.end());
    return out;
}

std::string DimensionEvaluations::text() const {
    if (listed.empty())
        return std::to_string(per_dimension) + "*dim";
    std::string out;
    for (const auto& [d, e] : listed)
        out += (out.empty() ? "dim" : "+dim") + std::to_string(d) + ":" + std::to_string(e);
    return out;
}

std::optional<std::int64_t> DimensionEvaluations::at(std::int64_t dimension) const {
    if (listed.empty()) {
        if (dimension < 1)
            return std::nullopt;
        if (per_dimension > max_budget_evaluations / dimension)
            throw std::invalid_argument("budget: evaluations = " + text() + " gives more than " +
                                        std::to_string(max_budget_evaluations) +
                                        " evaluations at dimension " + std::to_string(dimension));
        return per_dimension * dimension;
    }
    for (const auto& [d, e] : listed)
        if (d == dimension)
            return e;
    return std::nullopt;
}

std::string DimensionEvaluations::dimensions_text() const {
    std::string out;
    for (const auto& [d, e] : listed)
        out += (out.empty() ? "" : ", ") + std::to_string(d);
    return out;
}

std::optional<std::int64_t> budget_evaluations_at(std::string_view budget, std::int64_t dimension) {
    const SpecText spec = split_spec_text("budget:" + std::string(budget));
    const auto found = spec.parameters.find("evaluations");
    if (found == spec.parameters.end())
        return std::nullopt;
    try {
        if (DimensionEvaluations::written_in(found->second))
            return DimensionEvaluations::parse(found->second).at(dimension);
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
    std::int64_t count = 0;
    if (!parse_count(found->second, max_budget_evaluations, count))
        return std::nullopt;
    return count;
}

} // namespace mhb
