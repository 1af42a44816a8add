// A header-only C++ client of mhbench's external protocol (docs/extending.md, "External programs (any
// language)"), for a model or an optimiser built outside mhbench. Needs only nlohmann-json
// (Debian: nlohmann-json3-dev). Numbers go out with %.17g, so every double arrives exactly;
// infinities and NaN travel as the strings "inf", "-inf", "nan".
//
// A problem:   mhbench_external::serve_problem(version, describe, evaluate);
// An optimiser: mhbench_external::OptimizerClient client(version);
//               while (client.evaluate(points, values)) { ... client.iteration(); }
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace mhbench_external {

using Point = std::vector<double>;

inline std::string number(double v) {
    if (std::isnan(v))
        return "\"nan\"";
    if (std::isinf(v))
        return v > 0 ? "\"inf\"" : "\"-inf\"";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

inline std::string array(const Point& values) {
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0)
            out += ',';
        out += number(values[i]);
    }
    return out + "]";
}

inline double read_number(const nlohmann::json& v) {
    if (v.is_string()) {
        const auto& s = v.get_ref<const std::string&>();
        return s == "nan" ? std::numeric_limits<double>::quiet_NaN()
                          : (s == "-inf" ? -1.0 : 1.0) * std::numeric_limits<double>::infinity();
    }
    return v.get<double>();
}

inline Point read_point(const nlohmann::json& v) {
    Point out;
    for (const auto& x : v)
        out.push_back(read_number(x));
    return out;
}

inline void send(const std::string& line) {
    std::cout << line << '\n' << std::flush;
}

// The next message, or a null json when mhbench has closed our stdin.
inline nlohmann::json receive() {
    std::string line;
    if (!std::getline(std::cin, line))
        return nullptr;
    return nlohmann::json::parse(line);
}

using Parameters = std::map<std::string, std::string>;

inline Parameters parameters_of(const nlohmann::json& message) {
    Parameters out;
    if (message.contains("parameters"))
        for (const auto& [k, v] : message["parameters"].items())
            out[k] = v.get<std::string>();
    return out;
}

struct ProblemDescription {
    Point lower, upper;
    std::vector<std::string> names;  // optional
    std::optional<double> optimum_f; // optional
    Point truth{}; // optional: the parameters that generated the data (needs names); {} keeps
                   // aggregates written before it was added free of -Wmissing-field-initializers
};

// Serves a problem until mhbench closes our stdin: `describe` from the describe message's
// parameters, `evaluate` for each point of each batch.
inline int serve_problem(const std::string& version,
                         const std::function<ProblemDescription(const Parameters&)>& describe,
                         const std::function<double(const Point&)>& evaluate) {
    std::ios::sync_with_stdio(false); // std::cin read a character at a time otherwise
    for (nlohmann::json message = receive(); !message.is_null(); message = receive()) {
        const std::string type = message["type"];
        if (type == "describe") {
            const ProblemDescription d = describe(parameters_of(message));
            std::string line = R"({"type":"description","version":)" + nlohmann::json(version).dump() +
                               R"(,"dimension":)" + std::to_string(d.lower.size()) + R"(,"lower":)" +
                               array(d.lower) + R"(,"upper":)" + array(d.upper);
            if (!d.names.empty())
                line += R"(,"names":)" + nlohmann::json(d.names).dump();
            if (d.optimum_f)
                line += R"(,"optimum":{"f":)" + number(*d.optimum_f) + "}";
            if (!d.truth.empty())
                line += R"(,"truth":)" + array(d.truth);
            send(line + "}");
        } else if (type == "eval") {
            Point f;
            for (const auto& x : message["x"])
                f.push_back(evaluate(read_point(x)));
            send(R"({"type":"values","f":)" + array(f) + "}");
        }
    }
    return 0;
}

// The optimiser side: the constructor does the handshake and reads the start message.
class OptimizerClient {
public:
    explicit OptimizerClient(const std::string& version) {
        std::ios::sync_with_stdio(false); // std::cin read a character at a time otherwise
        const nlohmann::json describe = receive();
        if (describe.is_null())
            std::exit(0);
        parameters_ = parameters_of(describe);
        send(R"({"type":"description","version":)" + nlohmann::json(version).dump() + "}");
        const nlohmann::json start = receive();
        if (start.is_null() || start["type"] == "stop")
            std::exit(0);
        lower_ = read_point(start["lower"]);
        upper_ = read_point(start["upper"]);
        seed_ = start["seed"].get<std::uint64_t>();
    }

    [[nodiscard]] const Point& lower() const { return lower_; }
    [[nodiscard]] const Point& upper() const { return upper_; }
    [[nodiscard]] std::uint64_t seed() const { return seed_; }
    [[nodiscard]] const Parameters& parameters() const { return parameters_; }

    // Sends the points and reads back their values and repaired points (in place). Fewer come
    // back than were sent when the budget ended inside the batch. False when told to stop.
    bool evaluate(std::vector<Point>& points, Point& values) {
        std::string line = R"({"type":"eval","x":[)";
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (i > 0)
                line += ',';
            line += array(points[i]);
        }
        send(line + "]}");
        const nlohmann::json reply = receive();
        if (reply.is_null() || reply["type"] == "stop")
            return false;
        values = read_point(reply["f"]);
        points.clear();
        for (const auto& x : reply["x"])
            points.push_back(read_point(x));
        return true;
    }

    void initialised() { send(R"({"type":"initialised"})"); }
    void iteration() { send(R"({"type":"iteration"})"); }
    void done() { send(R"({"type":"done"})"); }

private:
    Point lower_, upper_;
    std::uint64_t seed_ = 0;
    Parameters parameters_;
};

} // namespace mhbench_external
