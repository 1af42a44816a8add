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

namespace {

std::vector<std::string> read_names(const nlohmann::json& names, std::size_t n) {
    if (!names.is_array() || names.size() != n)
        throw std::runtime_error("\"names\" is not an array of " + std::to_string(n) + " strings");
    std::vector<std::string> out;
    for (const auto& name : names) {
        if (!name.is_string())
            throw std::runtime_error("\"names\" holds something that is not a string");
        out.push_back(name.get<std::string>());
    }
    return out;
}

KnownOptimum read_optimum(const nlohmann::json& optimum, std::size_t n) {
    if (!optimum.is_object() || !optimum.contains("f"))
        throw std::runtime_error("\"optimum\" is not an object {\"f\": ..., \"x\": [...]}");
    KnownOptimum known;
    known.f = read_number(optimum.at("f"), "optimum f");
    if (optimum.contains("x") && !optimum.at("x").is_null())
        known.x = read_vector(optimum.at("x"), "optimum x", n);
    return known;
}

// The parameters that generated the problem's data. runs.csv reports them, and the errors against
// them, by name (P_true, P_err_pct): without names they would be silently dropped, so refused.
Eigen::VectorXd read_truth(const nlohmann::json& truth, std::size_t n, bool named) {
    if (!named)
        throw std::runtime_error(
            "\"truth\" needs \"names\" (runs.csv reports it by name: P_true, P_err_pct)");
    Eigen::VectorXd out = read_vector(truth, "truth", n);
    if (!out.allFinite())
        throw std::runtime_error("\"truth\" holds a value that is not a finite number");
    return out;
}

// What only a problem's description holds: its box, and what is known of it.
void read_problem_fields(const nlohmann::json& message, Description& d) {
    const auto dimension = message.find("dimension");
    if (dimension == message.end() || !dimension->is_number_integer() || dimension->get<long long>() < 1)
        throw std::runtime_error("the description has no positive integer \"dimension\"");
    const auto n = static_cast<std::size_t>(dimension->get<long long>());
    if (!message.contains("lower") || !message.contains("upper"))
        throw std::runtime_error("the description has no \"lower\" and \"upper\" bounds");
    d.bounds.lower = read_vector(message.at("lower"), "lower", n);
    d.bounds.upper = read_vector(message.at("upper"), "upper", n);
    if (const auto names = message.find("names"); names != message.end())
        d.names = read_names(*names, n);
    if (const auto optimum = message.find("optimum"); optimum != message.end() && !optimum->is_null())
        d.optimum = read_optimum(*optimum, n);
    if (const auto truth = message.find("truth"); truth != message.end() && !truth->is_null())
        d.truth = read_truth(*truth, n, !d.names.empty());
}

} // namespace

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
        if (role == "problem")
            read_problem_fields(message, d);
        return d;
    } catch (const ChildFault&) {
        throw;
    } catch (const std::exception& e) {
        throw ChildFault(link.program() + ": " + e.what(), link.stderr_tail());
    }
}

} // namespace mhb::external
