// A search bound as a problem family's spec takes it, `lo:hi` with finite lo < hi (e.g.
// `pmsm:rs=0:1`, `fluxmap:S=1:8`), shared so that every family reads and refuses it alike.
#pragma once

#include <stdexcept>
#include <string>

#include "problems/core/parameters.hpp"

namespace mhb {

// Reads `text` (the value of parameter `key` of `component`) into lo and hi, or throws
// std::invalid_argument naming both; `example` is a valid value shown in the message.
inline void parse_bound_text(const std::string& component, const std::string& key, const std::string& text,
                             const char* example, double& lo, double& hi) {
    const auto colon = text.find(':');
    if (colon == std::string::npos || !parse_real(text.substr(0, colon), lo) ||
        !parse_real(text.substr(colon + 1), hi))
        throw std::invalid_argument(component + ": parameter '" + key + "' = " + text +
                                    " is not of the form lo:hi (two finite numbers, e.g. " + example + ")");
    if (!(lo < hi))
        throw std::invalid_argument(component + ": parameter '" + key + "' = " + text + " needs lo < hi");
}

} // namespace mhb
