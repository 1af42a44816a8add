#include "results/protocols/protocol_registry.hpp"

#include <stdexcept>

#include "results/protocols/builtin_protocols.hpp"

namespace mhb {
namespace {

std::vector<std::unique_ptr<SuiteProtocol>>& registered_protocols() {
    static std::vector<std::unique_ptr<SuiteProtocol>> all = builtin_protocols();
    return all;
}

bool namable(const SuiteProtocol& protocol) {
    return !protocol.applies_unnamed();
}

} // namespace

void register_protocol(std::unique_ptr<SuiteProtocol> protocol) {
    if (!protocol)
        throw std::logic_error("register_protocol: no protocol");
    for (const auto& p : registered_protocols())
        if (p->name() == protocol->name())
            throw std::logic_error("protocol '" + std::string(protocol->name()) + "' is registered twice");
    registered_protocols().push_back(std::move(protocol));
}

const SuiteProtocol* find_protocol(std::string_view name) {
    for (const auto& p : registered_protocols())
        if (namable(*p) && p->name() == name)
            return p.get();
    return nullptr;
}

std::string protocol_names() {
    std::string out;
    for (const auto& p : registered_protocols())
        if (namable(*p))
            out += (out.empty() ? "" : ", ") + std::string(p->name());
    return out;
}

std::vector<const SuiteProtocol*> protocols_in_force(std::string_view named) {
    const SuiteProtocol* chosen = find_protocol(named);
    std::vector<const SuiteProtocol*> out;
    for (const auto& p : registered_protocols())
        if (p.get() == chosen || p->applies_unnamed())
            out.push_back(p.get());
    return out;
}

std::vector<const SuiteProtocol*> all_protocols() {
    std::vector<const SuiteProtocol*> out;
    for (const auto& p : registered_protocols())
        out.push_back(p.get());
    return out;
}

} // namespace mhb
