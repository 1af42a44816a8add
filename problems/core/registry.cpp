#include "problems/core/registry.hpp"

#include "problems/core/did_you_mean.hpp"

namespace mhb {

std::invalid_argument unknown_name(const std::string& kind, std::string_view name,
                                   const std::vector<std::string>& known) {
    return std::invalid_argument("unknown " + kind + " " + quoted_excerpt(name) +
                                 suggestion_or_known(name, known));
}

} // namespace mhb
