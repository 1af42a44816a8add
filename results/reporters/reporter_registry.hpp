// The reporters a report can use, by name: the built-ins (listed once, in reporter_registry.cpp)
// and those registered at run time by a test or a plug-in. The registry is process-wide; register
// before reports are built (it is not guarded against a report running in another thread).
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "results/reporters/reporter.hpp"

namespace mhb {

// Every reporter in the order a report calls them: the built-ins, then the registered ones.
const std::vector<std::shared_ptr<const Reporter>>& reporters();

// Adds a reporter after the others. Throws std::logic_error when its name is taken.
void register_reporter(std::shared_ptr<const Reporter> reporter);

// Removes the reporter of that name, if any (a test's own, after it).
void unregister_reporter(std::string_view name);

// The reporter of that name, or nullptr.
const Reporter* find_reporter(std::string_view name);

// The names --format accepts, in registration order.
std::vector<std::string> table_format_names();

// The table formats a report writes without --format.
std::set<std::string> default_table_formats();

// Why a --format selection cannot be used ("--format: 'pdf' is not one of md, tex, csv"), or none.
std::optional<std::string> table_format_error(const std::set<std::string>& formats);

// The reporters a report with those table formats uses: the formats and every every_report
// reporter, in registration order.
std::vector<const Reporter*> selected_reporters(const std::set<std::string>& formats);

} // namespace mhb
