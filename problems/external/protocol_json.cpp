#include "problems/external/protocol_json.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "problems/core/text_excerpt.hpp"

namespace mhb::external {

std::string json_number(double value) {
    if (std::isnan(value))
        return "\"nan\"";
    if (std::isinf(value))
        return value > 0 ? "\"inf\"" : "\"-inf\"";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

std::string json_array(std::span<const double> values) {
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0)
            out += ',';
        out += json_number(values[i]);
    }
    return out + ']';
}

std::string json_array(const Eigen::VectorXd& values) {
    return json_array(std::span<const double>(values.data(), static_cast<std::size_t>(values.size())));
}

std::string json_points(std::span<const Eigen::VectorXd> points) {
    std::string out = "[";
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i > 0)
            out += ',';
        out += json_array(points[i]);
    }
    return out + ']';
}

std::string json_string(std::string_view text) {
    return nlohmann::json(std::string(text)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json parse_message(std::string_view line) {
    // Python's json.dumps writes Infinity and NaN unless told otherwise; nlohmann refuses them.
    // They can only appear outside strings as bare words, which the replacement below turns into
    // the strings this protocol uses (a string that contains them is left alone: see inside).
    std::string text;
    text.reserve(line.size());
    bool inside = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (inside) {
            text += c;
            if (c == '\\' && i + 1 < line.size())
                text += line[++i];
            else if (c == '"')
                inside = false;
            continue;
        }
        if (c == '"')
            inside = true;
        if (line.substr(i, 8) == "Infinity") {
            text += "\"inf\"";
            i += 7;
        } else if (line.substr(i, 3) == "NaN") {
            text += "\"nan\"";
            i += 2;
        } else {
            text += c;
        }
    }
    // "-"inf"" from -Infinity: fold the sign into the string.
    for (std::size_t at = text.find("-\"inf\""); at != std::string::npos; at = text.find("-\"inf\""))
        text.replace(at, 6, "\"-inf\"");
    nlohmann::json message = nlohmann::json::parse(text, nullptr, false);
    if (message.is_discarded() || !message.is_object())
        // Most often a print meant for a person (a debug line, a warning of the model's library).
        throw std::runtime_error("wrote a line that is not a JSON object (" + quoted_excerpt(line) +
                                 "): stdout carries the protocol; print your own output to stderr");
    return message;
}

std::string message_type(const nlohmann::json& message) {
    const auto found = message.find("type");
    if (found == message.end() || !found->is_string())
        throw std::runtime_error("a message without a \"type\": " + quoted_excerpt(message.dump()));
    return found->get<std::string>();
}

double read_number(const nlohmann::json& value, const std::string& what) {
    if (value.is_number())
        return value.get<double>();
    if (value.is_string()) {
        const auto& s = value.get_ref<const std::string&>();
        if (s == "inf" || s == "+inf")
            return std::numeric_limits<double>::infinity();
        if (s == "-inf")
            return -std::numeric_limits<double>::infinity();
        if (s == "nan")
            return std::numeric_limits<double>::quiet_NaN();
    }
    throw std::runtime_error(what + " is not a number: " + quoted_excerpt(value.dump()));
}

std::vector<double> read_numbers(const nlohmann::json& value, const std::string& what,
                                 std::optional<std::size_t> size) {
    if (!value.is_array())
        throw std::runtime_error(what + " is not an array: " + quoted_excerpt(value.dump()));
    if (size && value.size() != *size)
        throw std::runtime_error(what + " has " + std::to_string(value.size()) + " numbers, not " +
                                 std::to_string(*size));
    std::vector<double> out;
    out.reserve(value.size());
    for (const auto& v : value)
        out.push_back(read_number(v, what));
    return out;
}

Eigen::VectorXd read_vector(const nlohmann::json& value, const std::string& what,
                            std::optional<std::size_t> size) {
    const std::vector<double> numbers = read_numbers(value, what, size);
    return Eigen::Map<const Eigen::VectorXd>(numbers.data(), static_cast<Eigen::Index>(numbers.size()));
}

} // namespace mhb::external
