#include "runner/execution/run_identity.hpp"

#include <map>
#include <sstream>

#include "problems/core/sha256.hpp"

namespace mhb {
namespace {

// "name = value" lines as a map (a value may hold " = ").
std::map<std::string, std::string> lines_of(const std::string& text) {
    std::map<std::string, std::string> values;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const auto eq = line.find(" = ");
        if (eq != std::string::npos)
            values[line.substr(0, eq)] = line.substr(eq + 3);
    }
    return values;
}

std::string value_or(const std::map<std::string, std::string>& values, const std::string& key,
                     const std::string& otherwise = "(none)") {
    const auto found = values.find(key);
    return found == values.end() ? otherwise : found->second;
}

// The fact line of an implementation version. Version 1 adds none, so that the runs stored
// before versions existed keep their identity; from 2 on it changes every identity.
std::string version_fact(const std::string& name, int version) {
    return version > 1 ? name + " = " + std::to_string(version) + '\n' : std::string();
}

// The fact line of a plug-in module's content; none for a built-in component, whose runs keep
// the identity they had before plug-ins existed.
std::string module_fact(const std::string& name, const DataFile& module) {
    return module.sha256.empty() ? std::string() : name + " = " + module.sha256 + '\n';
}

// The note naming a plug-in module's file, for messages.
std::string module_note(const std::string& name, const DataFile& module) {
    return module.path.empty() ? std::string() : name + " = " + module.path + '\n';
}

// The fact line of an external program's code and announced version (Problem::identity_facts,
// Optimizer::identity_facts); none for in-process components, whose identities stay as they were.
std::string program_fact(const std::string& name, const std::string& facts) {
    return facts.empty() ? std::string() : name + " = " + facts + '\n';
}

// "pso" of "pso:w=0.7".
std::string component_name(const std::string& spec) {
    return spec.substr(0, spec.find(':'));
}

} // namespace

RunKey run_key(const PreparedStudy& study, std::int64_t run_id) {
    const RunRequest request = study.request(run_id);
    const PreparedStudy::RunCell cell = study.cell(run_id);
    const PreparedAlgorithm& algorithm = study.algorithms[cell.algorithm];
    const PreparedProblem& problem = study.problems[cell.problem];
    RunKey key;
    key.algorithm = request.algorithm_spec;
    key.problem = request.problem_spec;
    key.facts = "format = " + std::to_string(store_format_version) + '\n' +
                "algorithm = " + request.algorithm_spec + '\n' +
                version_fact("algorithm version", algorithm.version) +
                module_fact("algorithm module", algorithm.module) +
                program_fact("algorithm program", algorithm.optimizer->identity_facts()) +
                "problem = " + problem.identity + '\n' + version_fact("problem version", problem.version) +
                module_fact("problem module", problem.module) +
                program_fact("problem program", problem.problem->identity_facts()) +
                "budget = " + request.budget_text + '\n' + "run = " + std::to_string(request.run_index) +
                '\n' + "seed = " + std::to_string(request.seed) + '\n';
    key.identity = sha256_hex(key.facts);
    const std::string& label = algorithm.info.label;
    key.slot = label + " | " + request.problem_spec + " | " + request.budget_text + " | " +
               std::to_string(request.run_index);
    key.notes = "label = " + label + '\n' + "problem as written = " + request.problem_spec + '\n' +
                "study seed = " + std::to_string(study.study.seed) + '\n' +
                "seeds = " + std::string(seed_mode_name(study.study.seeds)) + '\n' +
                module_note("algorithm module file", algorithm.module) +
                module_note("problem module file", problem.module);
    const auto files = problem.problem->data_files();
    for (std::size_t i = 0; i < files.size(); ++i)
        key.notes +=
            "data file " + std::to_string(i + 1) + " = " + files[i].sha256 + " " + files[i].path + '\n';
    return key;
}

StudyRunKeys study_run_keys(const PreparedStudy& study) {
    StudyRunKeys keys;
    keys.count = study.run_count();
    keys.key = [&study](std::int64_t run_id) { return run_key(study, run_id); };
    keys.names = [&study](std::int64_t run_id) {
        const PreparedStudy::RunCell c = study.cell(run_id);
        return std::make_pair(study.algorithms[c.algorithm].info.spec, study.problems[c.problem].spec);
    };
    keys.describe_change = describe_run_change;
    return keys;
}

std::string describe_run_change(const RunKey& stored, const RunKey& wanted) {
    const auto old_facts = lines_of(stored.facts);
    const auto new_facts = lines_of(wanted.facts);
    const auto old_notes = lines_of(stored.notes);
    const auto new_notes = lines_of(wanted.notes);
    const std::string problem = value_or(new_notes, "problem as written");
    if (value_or(old_facts, "format") != value_or(new_facts, "format"))
        return "the stored runs have record format " + value_or(old_facts, "format") +
               ", this mhbench writes " + value_or(new_facts, "format");
    for (const std::string kind : {"algorithm", "problem"}) {
        const std::string before = value_or(old_facts, kind + " version", "1");
        const std::string after = value_or(new_facts, kind + " version", "1");
        if (before != after)
            return kind + " '" + component_name(value_or(new_facts, kind)) +
                   "': the stored runs were made by version " + before + ", this mhbench has version " +
                   after;
    }
    // A plug-in module rebuilt (or replaced) under the same path.
    for (const std::string kind : {"algorithm", "problem"}) {
        const std::string before = value_or(old_facts, kind + " module", "(built in)");
        const std::string after = value_or(new_facts, kind + " module", "(built in)");
        if (before == after)
            continue;
        const std::string name = kind + " '" + component_name(value_or(new_facts, kind)) + "'";
        if (after == "(built in)")
            return name + ": the stored runs were made by plugin " +
                   value_or(old_notes, kind + " module file") + ", it is now built into mhbench";
        if (before == "(built in)")
            return name + ": the stored runs were made by mhbench's built-in " + kind +
                   ", it now comes from plugin " + value_or(new_notes, kind + " module file");
        return name + ": the plugin " + value_or(new_notes, kind + " module file") +
               " changed since the study started (sha256 " + short_hash(before) + " -> " + short_hash(after) +
               ")";
    }
    // An external program's code or announced version changed.
    for (const std::string kind : {"algorithm", "problem"}) {
        const std::string before = value_or(old_facts, kind + " program");
        const std::string after = value_or(new_facts, kind + " program");
        if (before != after)
            return kind + " '" + value_or(new_facts, kind) + "': the external program changed (" + before +
                   " -> " + after + ")";
    }
    if (value_or(old_facts, "problem") != value_or(new_facts, "problem")) {
        // A data file's content (its path is the same: the slot matched).
        for (int i = 1;; ++i) {
            const std::string key = "data file " + std::to_string(i);
            if (old_notes.count(key) == 0 || new_notes.count(key) == 0)
                break;
            const std::string before = old_notes.at(key).substr(0, old_notes.at(key).find(' '));
            const std::string after = new_notes.at(key).substr(0, new_notes.at(key).find(' '));
            if (before == after)
                continue;
            // With several files, say which one.
            const bool several = new_notes.count("data file 2") != 0;
            return problem + ": the file " +
                   (several ? new_notes.at(key).substr(after.size() + 1) + " " : "") +
                   "changed since the study started (sha256 " + short_hash(before) + " -> " +
                   short_hash(after) + ")";
        }
        return problem + ": the problem changed (" + value_or(old_facts, "problem") + " -> " +
               value_or(new_facts, "problem") + ")";
    }
    if (value_or(old_facts, "algorithm") != value_or(new_facts, "algorithm"))
        return "algorithm '" + value_or(new_notes, "label") + "': " + value_or(old_facts, "algorithm") +
               " -> " + value_or(new_facts, "algorithm");
    if (value_or(old_notes, "study seed") != value_or(new_notes, "study seed"))
        return "seed = " + value_or(new_notes, "study seed") +
               ", but the stored runs were made with seed = " + value_or(old_notes, "study seed");
    if (value_or(old_notes, "seeds") != value_or(new_notes, "seeds"))
        return "seeds = " + value_or(new_notes, "seeds") +
               ", but the stored runs were made with seeds = " + value_or(old_notes, "seeds");
    const auto flat = [](std::string text) {
        for (char& c : text)
            c = c == '\n' ? ';' : c;
        return text;
    };
    return "run " + wanted.slot + ": " + flat(stored.facts) + " -> " + flat(wanted.facts);
}

} // namespace mhb
