// A component as a user writes it: `name:key=value,key=value` (e.g. `pso:w=0.7`,
// `pmsm:data=drive.csv,rs=0:1`). Only the first ':' separates the name, so values may hold ':'.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mhb {

// `s` without the spaces and tabs at either end.
std::string_view trim_blanks(std::string_view s);

struct Spec {
    std::string name;
    // Key/value pairs in the order written; keys are unique.
    std::vector<std::pair<std::string, std::string>> parameters;

    // Throws std::invalid_argument naming the text and what is wrong with it.
    static Spec parse(std::string_view text);

    // `name:k1=v1,k2=v2` with keys sorted: the identity of a component, used for display and
    // for deriving seeds. Only the parameters actually written take part, so that adding a new
    // parameter with a default to an algorithm later leaves every existing stream unchanged.
    [[nodiscard]] std::string canonical() const;

    // The value written for `key`, or nullptr.
    [[nodiscard]] const std::string* find(std::string_view key) const;
};

} // namespace mhb
