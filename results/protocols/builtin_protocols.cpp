#include "results/protocols/builtin_protocols.hpp"

#include "results/analysis/cec_protocol.hpp"

namespace mhb {

// Each in its own file of this room.
std::unique_ptr<SuiteProtocol> cec_suite_protocol(const CecProtocol& rules); // cec_suite_protocol.cpp
std::unique_ptr<SuiteProtocol> pmsm_paper_protocol();                        // pmsm_paper_protocol.cpp

std::vector<std::unique_ptr<SuiteProtocol>> builtin_protocols() {
    std::vector<std::unique_ptr<SuiteProtocol>> out;
    for (const CecProtocol& rules : cec_protocols())
        out.push_back(cec_suite_protocol(rules));
    out.push_back(pmsm_paper_protocol());
    return out;
}

} // namespace mhb
