// The first exchange with an external program, for problems and optimisers alike:
//   mhbench -> {"type":"describe","protocol":1,"role":"problem"|"optimizer","parameters":{...}}
//   child   -> {"type":"description","version":"...", ...}
// A problem's description also gives its dimension, bounds and, optionally, coordinate names, a
// known optimum and the true parameters (`truth`, named coordinates only); an optimiser's gives
// only its version. Optional fields added later leave protocol_version as it is: a program that
// does not know them sends none, and an older mhbench ignores the fields it does not know.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "problems/external/child_link.hpp"
#include "problems/problem.hpp"

namespace mhb::external {

inline constexpr int protocol_version = 1;

struct Description {
    std::string version;
    // Problems only.
    Box bounds;
    std::vector<std::string> names;
    std::optional<KnownOptimum> optimum;
    std::optional<Eigen::VectorXd> truth; // finite, one per coordinate; may lie outside the box
};

// Sends `describe` and reads the description; ChildFault for a child that exits, times out or
// answers with something else. `role` is "problem" (bounds required) or "optimizer".
Description describe(ChildLink& link, const std::string& role,
                     const std::map<std::string, std::string>& parameters,
                     std::chrono::duration<double> timeout);

// `{"k":"v",...}` of the parameters.
std::string json_parameters(const std::map<std::string, std::string>& parameters);

// The fault's message with the child's last stderr lines appended, on one line.
std::string with_stderr(const ChildFault& fault);

} // namespace mhb::external
