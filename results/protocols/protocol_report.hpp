// What a report asks of the protocols in force at one budget (protocols_in_force,
// protocol_registry.hpp): their tables, where they stand, and their files.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "results/protocols/protocol_registry.hpp"

namespace mhb {

// The tables of every protocol in `protocols` placed at `place`, in their order.
std::vector<Table> protocol_tables(const std::vector<const SuiteProtocol*>& protocols,
                                   ProtocolTablesPlace place, const StudyIndex& index,
                                   const std::string& reference, double alpha);

// Whether a protocol of `protocols` writes files (write_protocol_files).
bool writes_protocol_files(const std::vector<const SuiteProtocol*>& protocols);

// Writes the files of `protocols` into the budget's report directory `dir` and removes those an
// earlier report wrote there for a protocol no longer in force (unless one in force writes the same
// folder).
void write_protocol_files(const std::vector<const SuiteProtocol*>& protocols, const StudyIndex& index,
                          const std::filesystem::path& dir, std::ostream& console);

} // namespace mhb
