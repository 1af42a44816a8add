// `mhbench merge OUT DIR...`: joins the directories of the shards of one study
// (`mhbench run --shard i/n`) into the directory one process would have written — the records
// byte for byte — and builds its report. Every shard is checked first: finished, of the same
// study, each of 1..n exactly once, holding exactly the runs its index is given, having read the
// same data (by SHA-256) with the same build (version, commit, dirty flag).
#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "results/report/report.hpp"
#include "results/store/csv.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_files.hpp"
#include "results/store/study_writer.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"
#include "runner/distribution/shards.hpp"
#include "runner/execution/companion_files.hpp"
#include "runner/execution/context.hpp"
#include "runner/execution/data_provenance.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/execution/run_identity.hpp"
#include "runner/execution/study_lock.hpp"
#include "runner/plugins/components.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"

namespace mhb::cli {

namespace po = boost::program_options;
namespace fs = std::filesystem;

namespace {

struct Shard {
    fs::path dir;
    ShardSpec spec;
    StudyData data;
};

// Reads and checks one shard directory; std::runtime_error naming it when it is not a shard.
Shard read_shard(const fs::path& dir) {
    if (!fs::exists(dir / StudyFiles::shard))
        throw std::runtime_error(dir.string() + ": is not a shard (no " + StudyFiles::shard +
                                 "); mhbench merge joins the directories of mhbench run --shard i/n");
    Shard s;
    s.dir = dir;
    std::string line = read_whole_file(dir / StudyFiles::shard);
    if (line.rfind("shard = ", 0) != 0 || line.empty() || line.back() != '\n')
        throw std::runtime_error((dir / StudyFiles::shard).string() + ": is not 'shard = i/n'");
    try {
        s.spec = parse_shard(std::string_view(line).substr(8, line.size() - 9));
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error((dir / StudyFiles::shard).string() + ": " + e.what());
    }
    s.data = load_study(dir); // says so when the shard is unfinished
    return s;
}

// One line per data file the shards read with different contents (from each other, or from the
// file as it is now, whose content the merged runs' identities will name) and per shard built
// otherwise than the first: study.ini names a file by its path, which says nothing of its content.
std::vector<std::string> provenance_errors(const std::map<int, const Shard*>& shards,
                                           const PreparedStudy& study) {
    const Shard& first = *shards.begin()->second;
    const DataFileHashes first_files = recorded_data_files(first.data.context_text);
    const std::string first_build = recorded_build(first.data.context_text);
    std::vector<std::string> errors;
    for (const auto& [index, shard] : shards) {
        const auto differences = data_file_differences(recorded_data_files(shard->data.context_text),
                                                       shard->dir.string(), first_files, first.dir.string());
        errors.insert(errors.end(), differences.begin(), differences.end());
        const std::string build = recorded_build(shard->data.context_text);
        if (build != first_build)
            errors.push_back(shard->dir.string() + ": was computed by " + build + ", " + first.dir.string() +
                             " by " + first_build);
    }
    if (!errors.empty())
        return errors;
    return data_file_differences(recorded_data_files(context_data_files(study.problems)), "the file now",
                                 first_files, first.dir.string());
}

// One study, one shard count, each index once, none missing: one line per way the shards fail
// that. `by_index` gets the shards by their index.
std::vector<std::string> shard_set_errors(const std::vector<Shard>& shards,
                                          std::map<int, const Shard*>& by_index) {
    std::vector<std::string> errors;
    const Shard& first = shards.front();
    for (const Shard& s : shards) {
        if (s.data.study_text != first.data.study_text)
            errors.push_back(s.dir.string() + ": holds another study than " + first.dir.string() +
                             " (their study.ini differ)");
        else if (s.spec.count != first.spec.count)
            errors.push_back(s.dir.string() + ": is shard " + shard_text(s.spec) + " of " +
                             std::to_string(s.spec.count) + ", but " + first.dir.string() + " is one of " +
                             std::to_string(first.spec.count));
        else if (const auto seen = by_index.find(s.spec.index); seen != by_index.end())
            errors.push_back("shard " + shard_text(s.spec) +
                             " is given twice: " + seen->second->dir.string() + " and " + s.dir.string());
        else
            by_index[s.spec.index] = &s;
    }
    if (errors.empty()) {
        std::string missing;
        for (int i = 1; i <= first.spec.count; ++i)
            if (by_index.count(i) == 0)
                missing += (missing.empty() ? "" : ", ") + shard_text({i, first.spec.count});
        if (!missing.empty())
            errors.push_back("shard" + std::string(missing.find(',') == std::string::npos ? " " : "s ") +
                             missing + (missing.find(',') == std::string::npos ? " is" : " are") +
                             " missing");
    }
    return errors;
}

// Each shard must hold exactly the runs its index is given; false, said, when one does not.
bool shards_hold_their_runs(const std::map<int, const Shard*>& by_index, const PreparedStudy& prepared,
                            int count) {
    const auto expected = shard_run_ids(prepared, count);
    for (const auto& [index, shard] : by_index) {
        std::vector<std::int64_t> ids;
        for (const auto& r : shard->data.runs)
            ids.push_back(r.run_id);
        if (ids != expected[static_cast<std::size_t>(index - 1)]) {
            std::cerr << "mhbench merge: " << shard->dir.string() << ": holds " << ids.size()
                      << " runs, not the " << expected[static_cast<std::size_t>(index - 1)].size()
                      << " runs of shard " << shard_text(shard->spec)
                      << " (was it run by another mhbench version?)\n";
            return false;
        }
    }
    return true;
}

// context.ini of the merged study: this session, the shards it came from, and every session that
// wrote into them.
std::string merged_context(const std::map<int, const Shard*>& by_index, const PreparedStudy& prepared,
                           int threads, const std::vector<std::string>& args) {
    std::vector<std::string> command_line{"mhbench", "merge"};
    command_line.insert(command_line.end(), args.begin(), args.end());
    std::string context = context_ini(threads > 0 ? threads : 1, command_line);
    context += "merged_from =";
    // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) on " " + a temporary here.
    for (const auto& [index, shard] : by_index)
        context.append(" ").append(shard->dir.string());
    context += "\nshards = " + std::to_string(by_index.begin()->second->spec.count) + '\n';
    std::string shard_sessions;
    for (const auto& [index, shard] : by_index)
        shard_sessions += context_sessions(shard->data.context_text);
    return context_with_history(context + context_data_files(prepared.problems), shard_sessions);
}

// Why OUT cannot take the merged study, or nothing. One of the shards would lose the runs the merge
// reads (always refused); a directory holding a study would lose its study, which needs
// --overwrite to say so. Paths are compared as files, not as text (./s1 and s1 are one).
struct OutRefusal {
    std::string message;
    int exit_code = exit_failure;
};
std::optional<OutRefusal> refuse_out(const fs::path& out, const std::vector<std::string>& dirs,
                                     bool overwrite) {
    std::error_code ec;
    for (std::size_t i = 1; i < dirs.size(); ++i)
        if (fs::equivalent(out, dirs[i], ec))
            return OutRefusal{"OUT " + out.string() + " is one of the shard directories to merge (" +
                                  dirs[i] + "); give another OUT",
                              exit_usage};
    if (overwrite)
        return std::nullopt;
    for (const char* record : {StudyFiles::marker, StudyFiles::study, StudyFiles::store})
        if (fs::exists(out / record, ec))
            return OutRefusal{"OUT " + out.string() + " holds a study (" + record +
                                  "); pass --overwrite to replace it, or give another OUT",
                              exit_failure};
    return std::nullopt;
}

po::options_description merge_options() {
    po::options_description visible(
        "Usage: mhbench merge OUT DIR... [options]\n\n"
        "Joins the n shard directories of one study (each made by mhbench run --shard i/n --out DIR)\n"
        "into the study directory OUT, with the records one process would have written, byte for\n"
        "byte, then builds its report. The shards must all be finished, of the same study, and be\n"
        "shards 1..n each exactly once. OUT is never one of them, and a directory that holds a study\n"
        "is refused unless --overwrite.\n\nOptions");
    visible.add_options()("help,h", "this text")(
        "overwrite", po::bool_switch(),
        "replace the study OUT holds (its store.bin, records and context.ini) with the merged one")(
        "threads", po::value<int>()->default_value(0), "recorded in context.ini (merging uses one)")(
        "no-report", po::bool_switch(), "do not build the report")(
        "no-figures", po::bool_switch(), "build the report without figures")("quiet,q", po::bool_switch(),
                                                                             "print nothing but errors");
    return visible;
}

} // namespace

int run_merge_command(const std::vector<std::string>& args) {
    const po::options_description visible = merge_options();
    po::options_description hidden;
    hidden.add_options()("dirs", po::value<std::vector<std::string>>()->multitoken());
    po::options_description all;
    all.add(visible).add(hidden);
    po::positional_options_description positional;
    positional.add("dirs", -1);
    po::variables_map vm;
    if (!parse_command_line(
            args, all, vm, [&] { std::cout << visible << '\n'; }, &positional))
        return exit_ok;
    const auto dirs =
        vm.count("dirs") ? vm["dirs"].as<std::vector<std::string>>() : std::vector<std::string>{};
    if (dirs.size() < 2) {
        std::cerr << "mhbench merge: give the output directory and at least one shard directory "
                     "(mhbench merge OUT DIR...; see --help)\n";
        return exit_usage;
    }
    const fs::path out = dirs.front();
    if (const auto refusal = refuse_out(out, dirs, vm["overwrite"].as<bool>())) {
        std::cerr << "mhbench merge: " << refusal->message << '\n';
        return refusal->exit_code;
    }

    std::vector<Shard> shards;
    for (std::size_t i = 1; i < dirs.size(); ++i) {
        shards.push_back(read_shard(dirs[i]));
        for (const std::string& warning : shards.back().data.warnings)
            std::cerr << "mhbench merge: warning: " << warning << '\n';
    }
    std::map<int, const Shard*> by_index;
    if (const auto errors = shard_set_errors(shards, by_index); !errors.empty()) {
        for (const auto& e : errors)
            std::cerr << "mhbench merge: " << e << '\n';
        return exit_failure;
    }
    const Shard& first = shards.front();

    // The study itself, to check that each shard holds exactly the runs its index is given.
    // Its plug-ins are loaded from the paths study.ini records (a PluginError is one line, exit 1).
    const Study study = parse_study_ini(first.data.study_text, "study.ini");
    const Components components = compose_components(study.plugins);
    const PreparedStudy prepared = prepare_study(study, components.algorithms, components.problems);
    if (!shards_hold_their_runs(by_index, prepared, first.spec.count))
        return exit_failure;
    if (const auto mixed = provenance_errors(by_index, prepared); !mixed.empty()) {
        for (const auto& e : mixed)
            std::cerr << "mhbench merge: " << e << '\n';
        std::cerr << "mhbench merge: the shards of a study must read the same data with the same build; run "
                     "the differing shards again\n";
        return exit_failure;
    }

    std::optional<StudyLock> lock; // one writer of OUT, from before its first byte to its report
    try {
        lock.emplace(out, "mhbench merge");
    } catch (const StudyInUse& e) {
        std::cerr << "mhbench merge: " << e.what() << "; wait for it or choose another OUT\n";
        return exit_failure;
    }
    StudyWriter writer(out, first.data.study_text,
                       merged_context(by_index, prepared, vm["threads"].as<int>(), args),
                       prepared.parameter_columns, vm["overwrite"].as<bool>(), prepared.algorithm_infos(),
                       study_run_keys(prepared));
    fs::remove(out / StudyFiles::shard); // the merged study is whole, even where a shard was replaced
    for (const auto& [index, shard] : by_index)
        for (const auto& record : shard->data.runs) {
            const auto wall = shard->data.wall_seconds.find(record.run_id);
            writer.append(record, wall == shard->data.wall_seconds.end() ? 0.0 : wall->second);
        }
    writer.finish();
    const bool quiet = vm["quiet"].as<bool>();
    if (!quiet)
        std::cout << "merged " << by_index.size() << " shards (" << prepared.run_count() << " runs) into "
                  << out.string() << '\n';
    if (vm["no-report"].as<bool>())
        return exit_ok;
    ReportOptions report;
    report.figures = !vm["no-figures"].as<bool>();
    report.plot_script = companion_file("scripts/plot_study.py");
    std::ostringstream discarded;
    return build_report(load_study(out), report, quiet ? discarded : std::cout).interrupted ? exit_interrupted
                                                                                            : exit_ok;
}

} // namespace mhb::cli
