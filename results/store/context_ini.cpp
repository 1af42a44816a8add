#include "results/store/context_ini.hpp"

#include <algorithm>

namespace mhb {

namespace {

std::string_view without_blank_ends(std::string_view s) {
    const std::size_t first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos)
        return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

} // namespace

std::vector<std::pair<std::string, std::string>> context_entries(std::string_view text) {
    std::vector<std::pair<std::string, std::string>> entries;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = without_blank_ends(text.substr(start, end - start));
        start = end + 1;
        const std::size_t equals = line.find('=');
        if (line.empty() || line[0] == '#' || line[0] == ';' || equals == std::string_view::npos)
            continue;
        entries.emplace_back(without_blank_ends(line.substr(0, equals)),
                             without_blank_ends(line.substr(equals + 1)));
    }
    return entries;
}

} // namespace mhb
