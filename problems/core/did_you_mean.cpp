#include "problems/core/did_you_mean.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

namespace mhb {

namespace {

char folded(char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

// The most edits a name of this length may be away from what was meant.
std::size_t edits_allowed(std::size_t length) {
    return length <= 4 ? 1 : length <= 8 ? 2 : 3;
}

bool begins_case_blind(std::string_view text, std::string_view prefix) {
    return prefix.size() <= text.size() && std::equal(prefix.begin(), prefix.end(), text.begin(),
                                                      [](char a, char b) { return folded(a) == folded(b); });
}

// The one candidate `name` begins, if exactly one.
std::vector<std::string> only_completion(std::string_view name, const std::vector<std::string>& candidates) {
    std::vector<std::string> found;
    if (name.size() < 3)
        return found;
    for (const auto& c : candidates)
        if (begins_case_blind(c, name))
            found.push_back(c);
    if (found.size() > 1)
        found.clear();
    return found;
}

} // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
    // Three rows of the dynamic programme: the row before the previous one is what a swap reads.
    std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = folded(a[i - 1]) == folded(b[j - 1]) ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + substitution});
            if (i > 1 && j > 1 && folded(a[i - 1]) == folded(b[j - 2]) &&
                folded(a[i - 2]) == folded(b[j - 1]))
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates) {
    if (auto completion = only_completion(name, candidates); !completion.empty())
        return completion; // a name cut short is nearer than any typo
    constexpr std::size_t most_shown = 3;
    std::size_t nearest = std::numeric_limits<std::size_t>::max();
    std::vector<std::string> found;
    for (const auto& c : candidates) {
        const std::size_t d = edit_distance(name, c);
        // Something of the name must survive: `x` is not a misspelt `r`.
        if (d >= name.size() || d > edits_allowed(name.size()) || d > nearest)
            continue;
        if (d < nearest) {
            nearest = d;
            found.clear();
        }
        if (found.size() < most_shown)
            found.push_back(c);
    }
    return found;
}

std::string did_you_mean(const std::vector<std::string>& suggestions) {
    if (suggestions.empty())
        return {};
    std::string out = "did you mean '" + suggestions.front() + "'";
    for (std::size_t i = 1; i < suggestions.size(); ++i)
        out += (i + 1 == suggestions.size() ? " or '" : ", '") + suggestions[i] + "'";
    return out + "?";
}

std::string suggestion_or_known(std::string_view name, const std::vector<std::string>& candidates) {
    if (auto near = closest_names(name, candidates); !near.empty())
        return "; " + did_you_mean(near);
    std::string known;
    for (const auto& c : candidates)
        known += (known.empty() ? "" : ", ") + c;
    return "; known: " + (known.empty() ? std::string("none") : known);
}

} // namespace mhb
