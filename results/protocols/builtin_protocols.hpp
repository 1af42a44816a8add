// The protocols mhbench brings, listed once (builtin_protocols.cpp): the CEC competitions' rules,
// one per competition of results/analysis/cec_protocol.hpp, and the paper's Tables 2-4. Internal
// to results/protocols/: everyone else asks protocol_registry.hpp.
#pragma once

#include <memory>
#include <vector>

#include "results/protocols/suite_protocol.hpp"

namespace mhb {

// In the registry's order: the order of protocol_names() and of the protocols in force.
std::vector<std::unique_ptr<SuiteProtocol>> builtin_protocols();

} // namespace mhb
