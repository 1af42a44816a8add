#include "runner/cli/format_option.hpp"

#include <sstream>
#include <vector>

#include "results/reporters/reporter_registry.hpp"
#include "results/table_model/table.hpp"

namespace mhb::cli {

std::string default_format_option() {
    const std::set<std::string> defaults = default_table_formats();
    std::vector<std::string> names;
    for (const auto& name : table_format_names())
        if (defaults.count(name) != 0)
            names.push_back(name);
    return join(names, ",");
}

std::string format_option_help() {
    return "table formats to write: any of " + join(table_format_names(), ",");
}

std::set<std::string> parse_format_option(const std::string& text) {
    std::set<std::string> formats;
    std::stringstream list(text);
    for (std::string f; std::getline(list, f, ',');) {
        const auto first = f.find_first_not_of(' ');
        if (first != std::string::npos)
            formats.insert(f.substr(first, f.find_last_not_of(' ') - first + 1));
    }
    return formats;
}

} // namespace mhb::cli
