#include "problems/core/parameters.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "problems/core/did_you_mean.hpp"
#include "problems/core/text_excerpt.hpp"

namespace mhb {

ParameterInfo ParameterInfo::real(std::string name, double default_value, double min, double max,
                                  std::string help) {
    ParameterInfo p;
    p.name = std::move(name);
    p.kind = ParameterKind::real;
    p.default_value = format_real(default_value);
    p.min = min;
    p.max = max;
    p.help = std::move(help);
    return p;
}

ParameterInfo ParameterInfo::integer(std::string name, long long default_value, long long min, long long max,
                                     std::string help) {
    ParameterInfo p;
    p.name = std::move(name);
    p.kind = ParameterKind::integer;
    p.default_value = std::to_string(default_value);
    p.min = static_cast<double>(min);
    p.max = static_cast<double>(max);
    p.help = std::move(help);
    return p;
}

ParameterInfo ParameterInfo::boolean(std::string name, bool default_value, std::string help) {
    ParameterInfo p;
    p.name = std::move(name);
    p.kind = ParameterKind::boolean;
    p.default_value = default_value ? "on" : "off";
    p.help = std::move(help);
    return p;
}

ParameterInfo ParameterInfo::choice(std::string name, std::string default_value,
                                    std::vector<std::string> choices, std::string help) {
    ParameterInfo p;
    p.name = std::move(name);
    p.kind = ParameterKind::choice;
    p.default_value = std::move(default_value);
    p.choices = std::move(choices);
    p.help = std::move(help);
    return p;
}

ParameterInfo ParameterInfo::text(std::string name, std::string default_value, std::string help) {
    ParameterInfo p;
    p.name = std::move(name);
    p.kind = ParameterKind::text;
    p.default_value = std::move(default_value);
    p.help = std::move(help);
    return p;
}

namespace {

// Integer bounds are shown in full (100000, not the shortest form 1e+05).
std::string bound_text(double v, bool integer) {
    if (std::isinf(v))
        return v > 0 ? "inf" : "-inf";
    if (integer)
        return std::to_string(static_cast<long long>(v));
    return format_real(v);
}

long long integer_bound(double v) {
    if (std::isnan(v) || v >= 9.2e18)
        return std::numeric_limits<long long>::max();
    return v <= -9.2e18 ? std::numeric_limits<long long>::min() : static_cast<long long>(v);
}

bool within(const ParameterInfo& p, double v) {
    const bool above = p.min_open ? v > p.min : v >= p.min;
    const bool below = p.max_open ? v < p.max : v <= p.max;
    return above && below;
}

} // namespace

std::string ParameterInfo::allowed() const {
    switch (kind) {
    case ParameterKind::real:
    case ParameterKind::integer:
        return std::string(min_open ? "(" : "[") + bound_text(min, kind == ParameterKind::integer) + ", " +
               bound_text(max, kind == ParameterKind::integer) + (max_open ? ")" : "]");
    case ParameterKind::boolean:
        return "{on, off}";
    case ParameterKind::choice: {
        std::string out = "{";
        for (std::size_t i = 0; i < choices.size(); ++i)
            out += (i ? ", " : "") + choices[i];
        return out + "}";
    }
    case ParameterKind::text:
        return "text";
    }
    return "";
}

bool parse_real(std::string_view text, double& out) {
    if (text.empty())
        return false;
    if (text.front() == '+')
        text.remove_prefix(1);
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end && std::isfinite(out);
}

bool parse_integer(std::string_view text, long long& out) {
    if (text.empty())
        return false;
    if (text.front() == '+')
        text.remove_prefix(1);
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    if (ec == std::errc() && ptr == end)
        return true;
    // Accept integral values written in scientific notation, e.g. maxeval=1e5.
    double d = 0;
    if (parse_real(text, d) && d == std::floor(d) && std::fabs(d) < 9.0e15) {
        out = static_cast<long long>(d);
        return true;
    }
    return false;
}

std::string integer_refusal(std::string_view text, long long min, long long max) {
    double d = 0;
    if (parse_real(text, d) && d == std::floor(d)) { // integral, but too far out for an integer
        if (d > 0)
            return "is too large (at most " + std::to_string(max) + ")";
        return "is too small (at least " + std::to_string(min) + ")";
    }
    // Digits only, and more of them than an integer holds (parse_real refuses beyond 1.8e308).
    const std::string_view digits =
        !text.empty() && (text.front() == '-' || text.front() == '+') ? text.substr(1) : text;
    if (!digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos)
        return text.front() == '-' ? "is too small (at least " + std::to_string(min) + ")"
                                   : "is too large (at most " + std::to_string(max) + ")";
    return "is not an integer";
}

bool parse_boolean(std::string_view text, bool& out) {
    if (text == "on" || text == "true" || text == "yes" || text == "1") {
        out = true;
        return true;
    }
    if (text == "off" || text == "false" || text == "no" || text == "0") {
        out = false;
        return true;
    }
    return false;
}

std::string format_real(double value) {
    // std::to_chars without a precision gives the shortest text that reads back exactly.
    char buf[64];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, result.ptr);
}

std::string normal_value(const ParameterInfo& info, std::string_view value) {
    switch (info.kind) {
    case ParameterKind::real: {
        double v = 0;
        return parse_real(value, v) ? format_real(v == 0.0 ? 0.0 : v) : std::string(value); // -0 is 0
    }
    case ParameterKind::integer: {
        long long v = 0;
        return parse_integer(value, v) ? std::to_string(v) : std::string(value);
    }
    case ParameterKind::boolean: {
        bool v = false;
        return parse_boolean(value, v) ? (v ? "on" : "off") : std::string(value);
    }
    case ParameterKind::choice:
    case ParameterKind::text:
        break;
    }
    return std::string(value);
}

void ParameterValues::set(std::string name, std::string value, bool given) {
    if (given)
        given_.insert(name);
    values_[std::move(name)] = std::move(value);
}

const std::string& ParameterValues::raw(std::string_view name) const {
    const auto it = values_.find(name);
    if (it == values_.end())
        throw std::logic_error("parameter '" + std::string(name) + "' was read but has no value");
    return it->second;
}

double ParameterValues::real(std::string_view name) const {
    double v = 0;
    if (!parse_real(raw(name), v))
        throw std::logic_error("parameter '" + std::string(name) + "' is not a number");
    return v;
}

long long ParameterValues::integer(std::string_view name) const {
    long long v = 0;
    if (!parse_integer(raw(name), v))
        throw std::logic_error("parameter '" + std::string(name) + "' is not an integer");
    return v;
}

bool ParameterValues::boolean(std::string_view name) const {
    bool v = false;
    if (!parse_boolean(raw(name), v))
        throw std::logic_error("parameter '" + std::string(name) + "' is not a boolean");
    return v;
}

const std::string& ParameterValues::text(std::string_view name) const {
    return raw(name);
}

bool ParameterValues::has(std::string_view name) const {
    return values_.find(name) != values_.end();
}

bool ParameterValues::given(std::string_view name) const {
    return given_.find(name) != given_.end();
}

ParameterValues validate_parameters(std::string_view component, const std::vector<ParameterInfo>& declared,
                                    const Spec& spec) {
    std::vector<std::string> errors;
    const std::string prefix = std::string(component) + ": parameter '";
    ParameterValues values;
    for (const auto& [key, value] : spec.parameters) {
        const ParameterInfo* info = nullptr;
        for (const auto& d : declared)
            if (d.name == key)
                info = &d;
        if (info == nullptr) {
            std::vector<std::string> known;
            for (const auto& d : declared)
                known.push_back(d.name);
            errors.push_back(std::string(component) + ": unknown parameter " + quoted_excerpt(key) +
                             suggestion_or_known(key, known));
            continue;
        }
        const std::string shown = prefix + key + "' = " + value_excerpt(value);
        switch (info->kind) {
        case ParameterKind::real: {
            double v = 0;
            if (!parse_real(value, v))
                errors.push_back(shown + " is not a finite number");
            else if (!within(*info, v))
                errors.push_back(shown + " is outside " + info->allowed());
            break;
        }
        case ParameterKind::integer: {
            long long v = 0;
            if (!parse_integer(value, v))
                errors.push_back(shown + " " +
                                 integer_refusal(value, integer_bound(info->min), integer_bound(info->max)));
            else if (!within(*info, static_cast<double>(v)))
                errors.push_back(shown + " is outside " + info->allowed());
            break;
        }
        case ParameterKind::boolean: {
            bool v = false;
            if (!parse_boolean(value, v))
                errors.push_back(shown + " is not one of on/off, true/false, yes/no, 1/0");
            break;
        }
        case ParameterKind::choice: {
            bool found = false;
            for (const auto& c : info->choices)
                found = found || c == value;
            if (!found)
                errors.push_back(shown + " is not one of " + info->allowed());
            break;
        }
        case ParameterKind::text:
            break;
        }
        values.set(key, value, true);
    }
    for (const auto& d : declared)
        if (!values.has(d.name) && !d.default_value.empty())
            values.set(d.name, d.default_value, false);
    if (!errors.empty()) {
        std::string joined;
        for (const auto& e : errors)
            joined += (joined.empty() ? "" : "\n") + e;
        throw std::invalid_argument(joined);
    }
    return values;
}

} // namespace mhb
