#include "runner/cli/run_options.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "runner/cli/format_option.hpp"
#include "runner/cli/rope_option.hpp"
#include "runner/study/study_file.hpp"
#include "runner/study/study_options.hpp"
#include "runner/study/study_presets.hpp"

namespace mhb::cli {
namespace po = boost::program_options;

namespace {

std::string preset_lines() {
    std::string out;
    for (const auto& p : study_presets()) {
        char line[256];
        std::snprintf(line, sizeof line, "    %-13s %s\n", p.name.c_str(), p.summary.c_str());
        out += line;
    }
    return out;
}

} // namespace

po::options_description make_run_options() {
    po::options_description run("Running");
    // clang-format off
    run.add_options()
        ("help,h", "this text")
        ("study", po::value<std::string>(), "start from a preset (see below); other options override its values")
        ("study-file", po::value<std::string>(),
         "start from a study file (scripts/studies/*.ini are examples, DIR/study.ini of an earlier study "
         "another); other options override its values")
        ("dry-run", po::bool_switch(),
         "print the expanded study (algorithms with their labels, problems, budgets, runs, evaluations, a "
         "time estimate from short calibration runs and each algorithm's share of it) and run nothing")
        ("shard", po::value<std::string>(),
         "i/n: run only shard i of n of the study (a deterministic share, balanced by estimated cost) into "
         "--out; `mhbench merge OUT DIR...` joins the n shard directories into the study one process writes "
         "(see scripts/slurm-array.sh)")
        ("threads", po::value<std::string>(), "worker threads (default: all hardware threads); results do not depend on it")
        ("out", po::value<std::string>(),
         "study directory (default: studies/<preset name, or 'study'>); the same command into it again "
         "resumes, and computes again the runs that failed")
        ("overwrite", po::bool_switch(),
         "empty the study store in --out and do every run again (needed when a data file, labelled "
         "algorithm or seed changed under stored runs)")
        ("recompute-changed", po::bool_switch(),
         "compute again the stored runs that something changed under (an algorithm's or problem's "
         "implementation version, a data file, a labelled algorithm, the seed) and keep every other "
         "stored run; without it such a study is refused")
        ("progress", po::bool_switch(), "draw the progress bar even when stderr is not a terminal")
        ("progress-interval", po::value<double>()->default_value(10.0, "10"),
         "seconds between the plain progress lines written when stderr is not a terminal (batch logs)")
        ("no-report", po::bool_switch(), "do not build the report (tables, curve data, figures) after the study; "
                                         "`mhbench report DIR` builds it at any time")
        ("no-figures", po::bool_switch(), "build the report without figures (they take most of its time)")
        ("format", po::value<std::string>()->default_value(default_format_option()), format_option_help().c_str())
        ("rope", po::value<double>()->default_value(default_log10_rope, format_number(default_log10_rope)), rope_option_help)
        ("raw-rope", po::value<double>(), raw_rope_option_help)
        ("tables", po::bool_switch(), "print every table of the report in Markdown before its verdict (the files hold them either way)")
        ("quiet,q", po::bool_switch(), "print nothing but errors (no progress bar, no summary, no verdict)");
    // clang-format on
    po::options_description all;
    all.add(study_options()).add(run);
    return all;
}

void print_run_help(const po::options_description& options) {
    std::cout
        << "Usage: mhbench run [options]\n\n"
           "Runs every algorithm on every problem under every budget, --runs times each, into a\n"
           "study directory (study.ini, context.ini, algorithms.csv, runs.csv, curves.csv, ...).\n"
           "The whole study, command line and study file together, is checked first and every\n"
           "error reported at once. By default every algorithm starts run r on a problem from the\n"
           "same random stream (common random numbers), so runs pair across algorithms and the\n"
           "report uses paired tests. Results are identical for any --threads. Every finished run is\n"
           "kept in DIR/store.bin: after Ctrl-C or a kill the same command resumes, and a larger\n"
           "study into the same --out (more runs, algorithms, problems, budgets) computes only the\n"
           "runs it lacks. Under `mpirun -np N` (an MPI build) the runs spread over the ranks.\n"
           "One process writes a directory at a time: while DIR/.mhbench.lock is held, another\n"
           "run, merge or report into DIR is refused with the holder's pid and host.\n\n"
        << options << "\nStudy presets (--study NAME; the files are in scripts/studies/):\n"
        << preset_lines()
        << "\nExamples:\n"
           "  mhbench run --study paper\n"
           "  mhbench run --study ablation --dry-run\n"
           "  mhbench run --study cec2017-smoke      # the CEC 2017 protocol, small\n"
           "  mhbench run --study cec2017 --problems \"cec2017:f={1,3-30},dim={10,30}\"\n"
           "  mhbench run --study paper --evaluations 37500 --out studies/paper-equal-evals\n"
           "  mhbench run --algorithms \"itlbo:tutorial={on,off},obl={on,off} tlbo\" \\\n"
           "              --problems sphere:dim=10 --budget iterations=200 --budget evaluations=2e4 \\\n"
           "              --runs 30 --out studies/sphere\n"
           "  mhbench run --study-file studies/sphere/study.ini --threads 1 --out /tmp/again\n";
}

bool load_base_study(const po::variables_map& vm, Study& study, std::string& name,
                     std::vector<std::string>& errors) {
    name = "study";
    if (vm.count("study") != 0 && vm.count("study-file") != 0) {
        errors.emplace_back("give --study or --study-file, not both");
        return false;
    }
    if (vm.count("study") != 0) {
        try {
            const StudyPreset& preset = find_study_preset(vm["study"].as<std::string>());
            study = preset.study;
            name = preset.name;
        } catch (const std::exception& e) {
            errors.emplace_back(e.what());
            return false;
        }
    } else if (vm.count("study-file") != 0) {
        const std::filesystem::path path = vm["study-file"].as<std::string>();
        std::string text;
        try {
            text = read_study_text(path);
        } catch (const std::exception& e) {
            errors.emplace_back(e.what());
            return false;
        }
        // Every error of the file is kept, with its line, and reported with the command line's;
        // after a line that is not `key = value`, "no algorithm given" and the like are noise.
        if (!parse_study_file(text, path.string(), study, errors))
            return false;
    }
    return true;
}

void apply_study_options(const po::variables_map& vm, Study& study, std::vector<std::string>& errors) {
    StudyOptionReader reader(study);
    const po::options_description declared = study_options();
    for (const auto& option : declared.options()) {
        const std::string& key = option->long_name();
        if (vm.count(key) == 0)
            continue;
        if (const auto* many = boost::any_cast<std::vector<std::string>>(&vm[key].value()))
            for (const auto& value : *many)
                reader.apply(key, value, "", errors);
        else
            reader.apply(key, vm[key].as<std::string>(), "", errors);
    }
    reader.finish(errors);
}

} // namespace mhb::cli
