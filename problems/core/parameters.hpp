// Typed, validated parameters of an optimiser or a problem family. A component declares its
// parameters once (name, kind, default, allowed range, help, source); the registry checks what
// the user wrote against that declaration before anything runs, and the declaration is what
// `mhbench list` and `--help` print.
#pragma once

#include <limits>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "problems/core/spec.hpp"

namespace mhb {

enum class ParameterKind { real, integer, boolean, choice, text };

struct ParameterInfo {
    std::string name;
    ParameterKind kind = ParameterKind::real;
    std::string default_value; // empty: the parameter is optional and has no default
    double min = -std::numeric_limits<double>::infinity(); // closed bounds unless *_open
    double max = std::numeric_limits<double>::infinity();
    bool min_open = false;
    bool max_open = false;
    std::vector<std::string> choices; // for ParameterKind::choice
    bool allows_range = false;        // integer written as `a-b` expands to one spec per value
    std::string help;                 // one line; says where the default comes from

    static ParameterInfo real(std::string name, double default_value, double min, double max,
                              std::string help);
    static ParameterInfo integer(std::string name, long long default_value, long long min, long long max,
                                 std::string help);
    static ParameterInfo boolean(std::string name, bool default_value, std::string help);
    static ParameterInfo choice(std::string name, std::string default_value, std::vector<std::string> choices,
                                std::string help);
    static ParameterInfo text(std::string name, std::string default_value, std::string help);

    // Make a bound exclusive: ParameterInfo::real("F", 0.5, 0, 2, "...").open_below().
    ParameterInfo open_below() && {
        min_open = true;
        return std::move(*this);
    }
    ParameterInfo open_above() && {
        max_open = true;
        return std::move(*this);
    }
    // Let an integer be written `a-b` to expand into one spec per value.
    ParameterInfo ranged() && {
        allows_range = true;
        return std::move(*this);
    }

    // `[0, 1]`, `(0, inf)`, `{on, off}`... as shown in errors and listings.
    [[nodiscard]] std::string allowed() const;
};

// Parameter values after validation: every declared parameter with a default is present.
class ParameterValues {
public:
    [[nodiscard]] double real(std::string_view name) const;
    [[nodiscard]] long long integer(std::string_view name) const;
    [[nodiscard]] bool boolean(std::string_view name) const;
    [[nodiscard]] const std::string& text(std::string_view name) const; // also for choices
    [[nodiscard]] bool has(std::string_view name) const;
    // True when the user wrote the parameter rather than taking its default.
    [[nodiscard]] bool given(std::string_view name) const;

    void set(std::string name, std::string value, bool given);

private:
    [[nodiscard]] const std::string& raw(std::string_view name) const;
    std::map<std::string, std::string, std::less<>> values_;
    std::set<std::string, std::less<>> given_;
};

// Checks `spec` against the declaration of `component` (e.g. "pso"). Every problem is reported
// in one std::invalid_argument, one line each, in the form
// `pso: parameter 'w' = 1.3 is outside [0, 1]`.
ParameterValues validate_parameters(std::string_view component, const std::vector<ParameterInfo>& declared,
                                    const Spec& spec);

// `value` (valid for `info`) in normal form: a real as its shortest round-trip text, an integer
// in decimal, a boolean as on/off, anything else as written. Two texts that mean the same value
// have the same normal form.
std::string normal_value(const ParameterInfo& info, std::string_view value);

// Strict number parsing for user input: the whole text must be a finite number.
bool parse_real(std::string_view text, double& out);
bool parse_integer(std::string_view text, long long& out);
bool parse_boolean(std::string_view text, bool& out);

// Why parse_integer refused `text`, for a value allowed in [min, max]: "is too large (at most
// max)" for an integral number beyond what an integer holds (1e300), "is too small (at least
// min)" below it, else "is not an integer".
std::string integer_refusal(std::string_view text, long long min, long long max);

// A double written as the shortest text that reads back to the same value.
std::string format_real(double value);

} // namespace mhb
