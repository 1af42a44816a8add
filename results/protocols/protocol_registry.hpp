// The suite protocols this mhbench knows (suite_protocol.hpp): the built-ins
// (builtin_protocols.cpp), then any registered at run time. What the runner includes of them.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "results/protocols/suite_protocol.hpp"

namespace mhb {

// Adds a protocol after the built-ins; a test adds its own this way. Throws std::logic_error when
// its name is taken.
void register_protocol(std::unique_ptr<SuiteProtocol> protocol);

// The protocol `protocol = NAME` names, or nullptr: not one a study may name (those in force
// unnamed are not).
const SuiteProtocol* find_protocol(std::string_view name);

// "cec2017, cec2022": the names a study may write, for messages.
std::string protocol_names();

// The protocols in force for a study that names `named` ("" for none): that one, when a study may
// name it, and every one in force unnamed, in the registry's order.
std::vector<const SuiteProtocol*> protocols_in_force(std::string_view named);

// Every protocol, in the registry's order.
std::vector<const SuiteProtocol*> all_protocols();

} // namespace mhb
