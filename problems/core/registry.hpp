// Creates components by name plus `key=value` parameters, so that the CLI, study files and tests
// build optimisers and problems the same way. Registration is explicit
// (`register_builtin_algorithms(registry)`), never static self-registration a linker may drop.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/core/spec.hpp"
#include "problems/core/text_excerpt.hpp"

namespace mhb {

// The error for a name no entry has: "unknown algorithm 'itlob'; did you mean 'itlbo'?", or the
// names known when none is near (problems/core/did_you_mean.hpp).
std::invalid_argument unknown_name(const std::string& kind, std::string_view name,
                                   const std::vector<std::string>& known);

// How reports name a component whose spec gives no `label=` (runner/study/default_label.cpp): a
// short display name, "PSO". An entry whose one parameter picks the method itself (nlopt's
// `algorithm`, cmaes's `restarts`) names each value instead: LN_BOBYQA -> "BOBYQA"; that parameter
// then joins no suffix of non-default parameters. Declared once, in the entry's registration.
struct DisplayName {
    std::string name; // "" for the entry's name
    std::string parameter{};
    std::vector<std::pair<std::string, std::string>> by_value{}; // value (normal form) -> display name
};

template <class Product> class Registry {
public:
    using Factory = std::function<std::unique_ptr<Product>(const ParameterValues&)>;

    struct Entry {
        std::string name;
        // The implementation version: bumped whenever what it computes changes (a fix, a new
        // default), so that a study never mixes stored runs of two versions. It joins the identity
        // of every run only from 2 on, so that runs stored before versions existed (version 1)
        // keep theirs. tests/data/implementation_versions.csv pins each version's numbers.
        int version = 1;
        std::string summary;   // one line for `mhbench list`
        std::string reference; // the paper (or library) it implements
        std::vector<ParameterInfo> parameters;
        Factory factory;
        // The plug-in module that registered the entry (runner/plugins/plugin_loader.hpp), empty for a
        // built-in one. Set by mhbench when it loads the module, not by the module: its SHA-256
        // joins the identity of every run of the entry, as a data file's does.
        std::string module_path{};
        std::string module_sha256{};
        DisplayName display{}; // add()'s second argument
    };

    // `kind` names what is registered ("algorithm", "problem") in error messages.
    explicit Registry(std::string kind) : kind_(std::move(kind)) {}

    void add(Entry entry, const DisplayName& display = {}) {
        if (!display.name.empty() || !display.parameter.empty())
            entry.display = display;
        for (const auto& e : entries_)
            if (e.name == entry.name)
                throw std::logic_error(kind_ + " '" + entry.name + "' is registered twice");
        entries_.push_back(std::move(entry));
    }

    [[nodiscard]] const Entry& find(std::string_view name) const {
        for (const auto& e : entries_)
            if (e.name == name)
                return e;
        throw unknown_name(kind_, name, names());
    }

    // The registered names, in registration order.
    [[nodiscard]] std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& e : entries_)
            out.push_back(e.name);
        return out;
    }

    [[nodiscard]] bool contains(std::string_view name) const {
        for (const auto& e : entries_)
            if (e.name == name)
                return true;
        return false;
    }

    [[nodiscard]] ParameterValues validate(const Spec& spec) const {
        return validate_parameters(spec.name, find(spec.name).parameters, spec);
    }

    // The spec validated, each written value in normal form (see normal_value: `w=0.50` is
    // `w=0.5`, `obl=false` is `obl=off`, `np=5e1` is `np=50`), keys sorted. Throws like validate().
    [[nodiscard]] Spec normalised(const Spec& spec) const {
        const Entry& entry = find(spec.name);
        (void)validate_parameters(spec.name, entry.parameters, spec);
        Spec out{spec.name, {}};
        for (const auto& [key, value] : spec.parameters)
            out.parameters.emplace_back(key, normal_value(declaration(entry, key), value));
        std::sort(out.parameters.begin(), out.parameters.end());
        return out;
    }

    // The identity of a component: normalised() without the parameters that equal their default,
    // so that `tlbo` and `tlbo:np=50` are one optimiser, whatever the text.
    [[nodiscard]] Spec minimal(const Spec& spec) const {
        const Entry& entry = find(spec.name);
        Spec out = normalised(spec);
        std::erase_if(out.parameters, [&](const auto& kv) {
            const ParameterInfo& p = declaration(entry, kv.first);
            return !p.default_value.empty() && normal_value(p, p.default_value) == kv.second;
        });
        return out;
    }

    // Every declared parameter with its value, given or default (normal form, keys sorted);
    // parameters without a default that were not given are left out.
    [[nodiscard]] Spec full(const Spec& spec) const {
        const Entry& entry = find(spec.name);
        Spec out = normalised(spec);
        for (const auto& p : entry.parameters)
            if (spec.find(p.name) == nullptr && !p.default_value.empty())
                out.parameters.emplace_back(p.name, normal_value(p, p.default_value));
        std::sort(out.parameters.begin(), out.parameters.end());
        return out;
    }

    // The declaration of parameter `key` of `entry` (which validation has already checked).
    [[nodiscard]] static const ParameterInfo& declaration(const Entry& entry, std::string_view key) {
        for (const auto& p : entry.parameters)
            if (p.name == key)
                return p;
        throw std::logic_error(entry.name + ": parameter '" + std::string(key) + "' is not declared");
    }

    [[nodiscard]] std::unique_ptr<Product> create(const Spec& spec) const {
        const Entry& entry = find(spec.name);
        return entry.factory(validate_parameters(spec.name, entry.parameters, spec));
    }

    [[nodiscard]] std::unique_ptr<Product> create(std::string_view text) const {
        return create(Spec::parse(text));
    }

    // Expands integer parameters declared with `allows_range` and written `a-b` into one spec
    // per value (e.g. `bbob:f=1-24,instance=1-5` gives 120 specs), in lexicographic order of the
    // ranges as written. Other parameters are left as they are.
    [[nodiscard]] std::vector<Spec> expand(const Spec& spec) const {
        const Entry& entry = find(spec.name);
        std::vector<Spec> out{Spec{spec.name, {}}};
        for (const auto& [key, value] : spec.parameters) {
            std::vector<std::string> values{value};
            for (const auto& p : entry.parameters) {
                if (p.name != key || !p.allows_range)
                    continue;
                const auto dash = value.find('-', 1);
                long long lo = 0;
                long long hi = 0;
                if (dash != std::string::npos && parse_integer(value.substr(0, dash), lo) &&
                    parse_integer(value.substr(dash + 1), hi)) {
                    if (hi < lo)
                        throw std::invalid_argument(spec.name + ": parameter '" + key + "' = " + value +
                                                    " is an empty range");
                    // The width in unsigned arithmetic, and a loop that stops at hi without passing
                    // it: ranges near the ends of long long must not overflow.
                    if (static_cast<unsigned long long>(hi) - static_cast<unsigned long long>(lo) >= 100000)
                        throw std::invalid_argument(spec.name + ": parameter '" + key + "' = " + value +
                                                    " is too long a range");
                    values.clear();
                    for (long long v = lo;; ++v) {
                        values.push_back(std::to_string(v));
                        if (v == hi)
                            break;
                    }
                }
            }
            std::vector<Spec> next;
            next.reserve(out.size() * values.size());
            for (const auto& partial : out)
                for (const auto& v : values) {
                    Spec s = partial;
                    s.parameters.emplace_back(key, v);
                    next.push_back(std::move(s));
                }
            out = std::move(next);
        }
        return out;
    }

    [[nodiscard]] const std::vector<Entry>& entries() const { return entries_; }
    [[nodiscard]] const std::string& kind() const { return kind_; }

private:
    std::string kind_;
    std::vector<Entry> entries_;
};

} // namespace mhb
