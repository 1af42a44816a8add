// The external protocol's wire format (README, "External programs (any language)"): one JSON
// object per line. Numbers are written with %.17g so that every double reads back to itself in
// any language; JSON has no infinity or NaN, so those travel as the strings "inf", "-inf" and
// "nan" (and Python's bare Infinity/-Infinity/NaN are accepted on reading, since json.dumps
// writes them by default).
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace mhb::external {

// `value` as a JSON number written with %.17g, or "inf", "-inf", "nan" as a JSON string.
std::string json_number(double value);
// `[a, b, ...]` of json_number.
std::string json_array(std::span<const double> values);
std::string json_array(const Eigen::VectorXd& values);
// `[[...], [...]]`, one inner array per point.
std::string json_points(std::span<const Eigen::VectorXd> points);
// `text` as a JSON string, escaped.
std::string json_string(std::string_view text);

// Parses one line into a JSON object; std::runtime_error saying "wrote a line that is not a JSON
// object ('<excerpt>'): stdout carries the protocol; ..." (after the program's name and ": ").
nlohmann::json parse_message(std::string_view line);
// The message's "type" (a string), or std::runtime_error.
std::string message_type(const nlohmann::json& message);

// A number, or one of the strings above. std::runtime_error naming `what` otherwise.
double read_number(const nlohmann::json& value, const std::string& what);
// An array of numbers; `size` checked when given.
std::vector<double> read_numbers(const nlohmann::json& value, const std::string& what,
                                 std::optional<std::size_t> size = std::nullopt);
Eigen::VectorXd read_vector(const nlohmann::json& value, const std::string& what,
                            std::optional<std::size_t> size = std::nullopt);

} // namespace mhb::external
