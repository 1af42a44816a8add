#include "problems/external/handshake.hpp"

#include <stdexcept>

#include "problems/external/protocol_json.hpp"

namespace mhb::external {

std::string json_parameters(const std::map<std::string, std::string>& parameters) {
    std::string out = "{";
    for (const auto& [key, value] : parameters) {
        if (out.size() > 1)
            out += ',';
        out.append(json_string(key)).append(":").append(json_string(value));
    }
    return out + "}";
}

std::string with_stderr(const ChildFault& fault) {
    return fault.stderr_tail().empty() ? std::string(fault.what())
                                       : std::string(fault.what()) + "; its stderr: " + fault.stderr_tail();
}

Description describe(ChildLink& link, const std::string& role,
                     const std::map<std::string, std::string>& parameters,
                     std::chrono::duration<double> timeout) {
    link.send(R"({"type":"describe","protocol":)" + std::to_string(protocol_version) + R"(,"role":)" +
              json_string(role) + R"(,"parameters":)" + json_parameters(parameters) + "}");
    const std::string line = link.receive(timeout);
    // Every protocol error below is the child's fault: the same ChildFault as a crash, with its
    // stderr (a Python traceback usually says why).
    try {
        const nlohmann::json message = parse_message(line);
        if (message_type(message) != "description")
            throw std::runtime_error("answered describe with " + message_type(message));
        Description d;
        const auto version = message.find("version");
        if (version == message.end() || !version->is_string() || version->get<std::string>().empty())
            throw std::runtime_error("the description has no \"version\" string");
        d.version = version->get<std::string>();
        if (role != "problem")
            return d;
        const auto dimension = message.find("dimension");
        if (dimension == message.end() || !dimension->is_number_integer() || dimension->get<long long>() < 1)
            throw std::runtime_error("the description has no positive integer \"dimension\"");
        const auto n = static_cast<std::size_t>(dimension->get<long long>());
        if (!message.contains("lower") || !message.contains("upper"))
            throw std::runtime_error("the description has no \"lower\" and \"upper\" bounds");
        d.bounds.lower = read_vector(message.at("lower"), "lower", n);
        d.bounds.upper = read_vector(message.at("upper"), "upper", n);
        if (const auto names = message.find("names"); names != message.end()) {
            if (!names->is_array() || names->size() != n)
                throw std::runtime_error("\"names\" is not an array of " + std::to_string(n) + " strings");
            for (const auto& name : *names) {
                if (!name.is_string())
                    throw std::runtime_error("\"names\" holds something that is not a string");
                d.names.push_back(name.get<std::string>());
            }
        }
        if (const auto optimum = message.find("optimum"); optimum != message.end() && !optimum->is_null()) {
            if (!optimum->is_object() || !optimum->contains("f"))
                throw std::runtime_error("\"optimum\" is not an object {\"f\": ..., \"x\": [...]}");
            KnownOptimum known;
            known.f = read_number(optimum->at("f"), "optimum f");
            if (optimum->contains("x") && !optimum->at("x").is_null())
                known.x = read_vector(optimum->at("x"), "optimum x", n);
            d.optimum = known;
        }
        return d;
    } catch (const ChildFault&) {
        throw;
    } catch (const std::exception& e) {
        throw ChildFault(link.program() + ": " + e.what(), link.stderr_tail());
    }
}

} // namespace mhb::external
