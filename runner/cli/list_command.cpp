// `mhbench list [algorithms|problems|studies [NAME]|formats]`: what can be named in a study, with each
// entry's summary, reference and parameters (default, allowed values, meaning), and the outputs a
// report writes. Printed straight from the registries' declarations, so it can never disagree
// with what the code accepts.
#include <algorithm>
#include <boost/program_options.hpp>
#include <cstdio>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/did_you_mean.hpp"
#include "problems/core/text_excerpt.hpp"
#include "problems/problem_registry.hpp"
#include "results/reporters/reporter_registry.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"
#include "runner/plugins/components.hpp"
#include "runner/study/study_presets.hpp"

namespace mhb::cli {
namespace po = boost::program_options;

namespace {

// One entry in full: name, version, summary, reference, plug-in and its parameters' table.
template <class Entry> void print_entry(std::ostream& out, const Entry& entry) {
    out << "  " << entry.name << " (version " << entry.version << ")\n      " << entry.summary << '\n';
    if (!entry.reference.empty())
        out << "      reference: " << entry.reference << '\n';
    if (!entry.module_path.empty())
        out << "      plugin: " << entry.module_path << '\n';
    if (entry.parameters.empty()) {
        out << "      no parameters\n";
        return;
    }
    // Columns sized to this entry's parameters, so each table reads straight down.
    std::size_t name_width = 9; // "parameter"
    std::size_t default_width = 7;
    std::size_t allowed_width = 7;
    for (const auto& p : entry.parameters) {
        name_width = std::max(name_width, p.name.size());
        default_width = std::max(default_width, p.default_value.empty() ? 6 : p.default_value.size());
        allowed_width = std::max(allowed_width, p.allowed().size() + (p.allows_range ? 9 : 0));
    }
    const auto row = [&](const std::string& a, const std::string& b, const std::string& c,
                         const std::string& d) {
        out << "      " << a << std::string(name_width - a.size() + 2, ' ') << b
            << std::string(default_width - b.size() + 2, ' ') << c
            << std::string(allowed_width - c.size() + 2, ' ') << d << '\n';
    };
    row("parameter", "default", "allowed", "meaning");
    for (const auto& p : entry.parameters)
        row(p.name, p.default_value.empty() ? "(none)" : p.default_value,
            p.allowed() + (p.allows_range ? " or a-b" : ""), p.help);
}

// "itlbo:np=30": how an entry is written, with its first parameter at its default.
template <class Entry> std::string example_spec(const Entry& entry) {
    return entry.name + (entry.parameters.empty() ? std::string()
                                                  : ":" + entry.parameters.front().name + "=" +
                                                        entry.parameters.front().default_value);
}

template <class Product>
void print_registry(std::ostream& out, const char* title, const Registry<Product>& registry) {
    out << title << " (" << registry.entries().size() << ")\n";
    for (const auto& entry : registry.entries()) {
        out << '\n';
        print_entry(out, entry);
    }
    out << "\nWrite a component as name:key=value,... e.g. "
        << (registry.entries().empty() ? std::string("name:key=value")
                                       : example_spec(registry.entries().front()))
        << "\n\n";
}

void print_study(std::ostream& out, const StudyPreset& p) {
    out << "  " << p.name << "\n      " << p.summary << "\n      algorithms:";
    for (const auto& a : p.study.algorithms)
        out << ' ' << a;
    out << "\n      problems:";
    for (const auto& q : p.study.problems)
        out << ' ' << q;
    out << "\n      runs: " << p.study.runs << ", seeds: " << seed_mode_name(p.study.seeds) << ", budgets:";
    for (const auto& b : p.study.budgets)
        out << ' ' << budget_text(b);
    if (!p.study.protocol.empty())
        out << "\n      protocol: " << p.study.protocol << " (the competition's tables and result files)";
    out << "\n      file: " << p.origin;
    out << "\n\n";
}

void print_studies(std::ostream& out) {
    out << "Study presets (" << study_presets().size() << "), for mhbench run --study NAME\n\n";
    for (const auto& p : study_presets())
        print_study(out, p);
}

// The reporters: the table formats --format chooses from, then what every report writes.
void print_formats(std::ostream& out) {
    const std::set<std::string> defaults = default_table_formats();
    out << "Output formats (" << reporters().size() << "): table formats for --format of mhbench report and "
        << "mhbench run, then what every report writes\n\n";
    for (const ReporterKind kind : {ReporterKind::table_format, ReporterKind::every_report})
        for (const auto& reporter : reporters()) {
            if (reporter->kind() != kind)
                continue;
            const std::string name(reporter->name());
            out << "  " << name
                << (kind == ReporterKind::every_report ? " (every report)"
                    : defaults.count(name) != 0        ? " (table format, default)"
                                                       : " (table format)")
                << "\n      " << reporter->description() << '\n';
        }
    out << '\n';
}

// `mhbench list KIND NAME`: the one entry in full; an unknown name gets the registry's "did you
// mean" (std::invalid_argument, exit 2 from main).
int print_one(const std::string& what, const std::string& name, const Components& components) {
    if (what == "algorithms" || what == "problems") {
        const auto print = [&](const auto& registry) {
            const auto& entry = registry.find(name);
            print_entry(std::cout, entry);
            std::cout << "\nWrite it as name:key=value,... e.g. " << example_spec(entry) << '\n';
        };
        if (what == "algorithms")
            print(components.algorithms);
        else
            print(components.problems);
    } else if (what == "studies") {
        print_study(std::cout, find_study_preset(name));
    } else {
        throw std::invalid_argument("a name follows only algorithms, problems or studies, not " + what);
    }
    return exit_ok;
}

} // namespace

int run_list_command(const std::vector<std::string>& args) {
    po::options_description options("Options");
    options.add_options()("help,h", "this text")(
        "what", po::value<std::string>(), "algorithms, problems, studies (default: these three) or formats")(
        "name", po::value<std::string>(), "one algorithm, problem family or study preset, shown alone")(
        "plugin", po::value<std::vector<std::string>>()->composing(),
        "also list the optimisers and problems of this plug-in module (repeatable)");
    po::positional_options_description positional;
    positional.add("what", 1).add("name", 1);
    po::variables_map vm;
    const auto print_help = [&] {
        std::cout << "Usage: mhbench list [algorithms|problems|studies [NAME]] [--plugin lib.so ...]\n"
                     "       mhbench list formats\n\n"
                     "Lists what a study can name: every registered optimiser and problem family with its\n"
                     "summary, reference and parameters (default, allowed values, meaning), and the study\n"
                     "presets of mhbench run --study; with a NAME, that one alone; `formats`: the outputs a\n"
                     "report writes (the table formats of --format, the exports).\n\n"
                  << options
                  << "\nExamples:\n  mhbench list\n  mhbench list algorithms\n  mhbench list problems pmsm\n";
    };
    if (!parse_command_line(args, options, vm, print_help, &positional))
        return exit_ok;
    const std::string what = vm.count("what") != 0 ? vm["what"].as<std::string>() : "all";
    const bool all = what == "all";
    if (what == "formats" && vm.count("name") == 0) {
        print_formats(std::cout);
        return exit_ok;
    }
    if (!all && what != "algorithms" && what != "problems" && what != "studies" && what != "formats") {
        std::cerr << "mhbench list: unknown list " << quoted_excerpt(what)
                  << suggestion_or_known(what, {"algorithms", "problems", "studies", "formats"}) << '\n';
        return exit_usage;
    }
    // A module that cannot be used: one line from main (PluginError), exit 1.
    const Components components = compose_components(
        vm.count("plugin") != 0 ? vm["plugin"].as<std::vector<std::string>>() : std::vector<std::string>{});
    if (vm.count("name") != 0)
        return print_one(what, vm["name"].as<std::string>(), components);
    if (all || what == "algorithms")
        print_registry(std::cout, "Algorithms", components.algorithms);
    if (all || what == "problems")
        print_registry(std::cout, "Problems", components.problems);
    if (all || what == "studies")
        print_studies(std::cout);
    return exit_ok;
}

} // namespace mhb::cli
