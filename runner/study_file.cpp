#include "runner/study_file.hpp"

#include "problems/parameters.hpp"
#include "problems/spec.hpp"

#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mhb {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

} // namespace

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
    Study study;
    bool seen_runs = false;
    bool seen_seed = false;
    std::size_t line_number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const auto end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++line_number;
        // As in Boost.Program_options config files, '#' starts a comment anywhere on a line.
        line = trim(line.substr(0, line.find('#')));
        if (line.empty())
            continue;
        const std::string where = origin + ", line " + std::to_string(line_number) + ": ";
        const auto eq = line.find('=');
        if (eq == std::string_view::npos)
            throw std::invalid_argument(where + "'" + std::string(line) + "' is not key = value");
        const std::string key(trim(line.substr(0, eq)));
        const std::string value(trim(line.substr(eq + 1)));
        const auto fail = [&](const std::string& why) -> void {
            throw std::invalid_argument(where + "'" + key + " = " + value + "' " + why);
        };
        const auto read_integer = [&](std::int64_t& out, bool& seen) {
            if (seen)
                fail("is given twice");
            long long v = 0;
            if (!parse_integer(value, v))
                fail("is not an integer");
            out = v;
            seen = true;
        };
        if (key == "algorithm" || key == "problem") {
            // Several specs may share a line, separated by spaces, as on the command line.
            auto& list = key == "algorithm" ? study.algorithms : study.problems;
            for (auto& spec : split_spec_list(value))
                list.push_back(std::move(spec));
        } else if (key == "runs") {
            read_integer(study.runs, seen_runs);
        } else if (key == "seed") {
            if (seen_seed)
                fail("is given twice");
            const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), study.seed);
            if (value.empty() || ec != std::errc() || ptr != value.data() + value.size())
                fail("is not an integer in [0, 2^64)");
            seen_seed = true;
        } else if (key == "iterations" || key == "evaluations") {
            auto& slot = key == "iterations" ? study.budget.max_iterations : study.budget.max_evaluations;
            bool seen = slot.has_value();
            std::int64_t v = 0;
            read_integer(v, seen);
            slot = v;
        } else if (key == "target") {
            double v = 0;
            if (study.budget.target_error)
                fail("is given twice");
            if (!parse_real(value, v))
                fail("is not a finite number");
            study.budget.target_error = v;
        } else {
            throw std::invalid_argument(where + "unknown key '" + key +
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
