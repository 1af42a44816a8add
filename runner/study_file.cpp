#include "runner/study_file.hpp"

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/parsers.hpp>
#include <charconv>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "problems/parameters.hpp"
#include "problems/spec.hpp"

namespace mhb {
std::string study_ini(const Study& study) {
    std::string text = "# mhbench study. Run it again with: mhbench run --study-file study.ini --out DIR\n"
                       "# Threads and output directory are not part of a study: they do not change results.\n"
                       "# Each run's seed is derived from seed, algorithm, problem and run index.\n";
    for (const auto& a : study.algorithms)
        text += "algorithm = " + a + '\n';
    for (const auto& p : study.problems)
        text += "problem = " + p + '\n';
    text += "runs = " + std::to_string(study.runs) + '\n';
    text += "seed = " + std::to_string(study.seed) + '\n';
    if (study.budget.max_iterations)
        text += "iterations = " + std::to_string(*study.budget.max_iterations) + '\n';
    if (study.budget.max_evaluations)
        text += "evaluations = " + std::to_string(*study.budget.max_evaluations) + '\n';
    if (study.budget.target_error)
        text += "target = " + format_real(*study.budget.target_error) + '\n';
    return text;
}

Study parse_study_ini(std::string_view text, const std::string& origin) {
    // Boost.Program_options reads the syntax (key = value, '#' comments, sections); the values are
    // checked here, so that every error names the file, the key and the value.
    namespace po = boost::program_options;
    std::istringstream stream{std::string(text)};
    po::parsed_options parsed(nullptr);
    try {
        const po::options_description none;
        parsed = po::parse_config_file(stream, none, /*allow_unregistered=*/true);
    } catch (const po::error& e) {
        throw std::invalid_argument(origin + ": " + e.what());
    }
    Study study;
    std::set<std::string> seen;
    for (const auto& option : parsed.options) {
        const std::string& key = option.string_key;
        const std::string value = option.value.empty() ? std::string() : option.value.front();
        const auto fail = [&](const std::string& why) {
            throw std::invalid_argument(origin + ": '" + key + " = " + value + "' " + why);
        };
        const bool single = key != "algorithm" && key != "problem";
        if (single && !seen.insert(key).second)
            fail("is given twice");
        const auto read_integer = [&]() -> std::int64_t {
            long long v = 0;
            if (!parse_integer(value, v))
                fail("is not an integer");
            return v;
        };
        if (key == "algorithm" || key == "problem") {
            // Several specs may share a line, separated by spaces, as on the command line.
            auto& list = key == "algorithm" ? study.algorithms : study.problems;
            for (auto& spec : split_spec_list(value))
                list.push_back(std::move(spec));
        } else if (key == "runs") {
            study.runs = read_integer();
        } else if (key == "seed") {
            const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), study.seed);
            if (value.empty() || ec != std::errc() || ptr != value.data() + value.size())
                fail("is not an integer in [0, 2^64)");
        } else if (key == "iterations") {
            study.budget.max_iterations = read_integer();
        } else if (key == "evaluations") {
            study.budget.max_evaluations = read_integer();
        } else if (key == "target") {
            double v = 0;
            if (!parse_real(value, v))
                fail("is not a finite number");
            study.budget.target_error = v;
        } else {
            throw std::invalid_argument(origin + ": unknown key '" + key +
                                        "'; known: algorithm, problem, runs, seed, iterations, evaluations, "
                                        "target");
        }
    }
    return study;
}

Study read_study_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path.string() + ": cannot be opened (missing?)");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return parse_study_ini(buffer.str(), path.string());
}

} // namespace mhb
