// --format of `mhbench report` and `mhbench run`: the table formats a report writes, named as their
// reporters are registered (results/reporters/reporter_registry.hpp), so a new format is accepted,
// listed in the help and defaulted without a change here.
#pragma once

#include <set>
#include <string>

namespace mhb::cli {

// The formats a report writes without --format, comma-separated in registration order: "md,tex,csv".
std::string default_format_option();

// The option's help: "table formats to write: any of md,tex,csv".
std::string format_option_help();

// The names of a --format value: "md, tex" is meant as "md,tex"; empty items are dropped.
std::set<std::string> parse_format_option(const std::string& text);

} // namespace mhb::cli
