#include "runner/study/study_file.hpp"

#include <boost/program_options/parsers.hpp>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "problems/core/parameters.hpp"
#include "problems/core/text_excerpt.hpp"
#include "runner/study/study_options.hpp"

namespace mhb {
namespace {

std::string trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return std::string(s);
}

struct LogicalLine {
    std::size_t number = 0; // of its first physical line
    std::string text;
};

// Physical lines joined into logical ones: comments removed, a trailing backslash or an indented
// line continues the line above.
std::vector<LogicalLine> logical_lines(std::string_view text) {
    std::vector<LogicalLine> out;
    bool continued = false;
    std::size_t number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const auto end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++number;
        line = line.substr(0, std::min(line.find('#'), line.size()));
        const bool indented = !line.empty() && (line.front() == ' ' || line.front() == '\t');
        std::string content = trim(line);
        const bool continues = !content.empty() && content.back() == '\\';
        if (continues)
            content = trim(std::string_view(content).substr(0, content.size() - 1));
        if ((continued || (indented && !content.empty())) && !out.empty()) {
            if (!content.empty())
                out.back().text += " " + content;
        } else if (!content.empty() || continues) {
            out.push_back({number, content});
        }
        continued = continues;
    }
    return out;
}

} // namespace

std::string study_ini(const Study& study) {
    std::string text =
        "# mhbench study. Run it again with: mhbench run --study-file study.ini --out DIR\n"
        "# Threads and output directory are not part of a study: they do not change results.\n"
        "# Seeds: 'common' derives run r's stream on problem p from (seed, problem, r) alone,\n"
        "# the same for every algorithm; 'per-algorithm' also from the algorithm.\n";
    for (const auto& a : study.algorithms)
        text += "algorithms = " + a + '\n';
    for (const auto& p : study.problems)
        text += "problems = " + p + '\n';
    if (const auto& rule = study.by_precision) { // only then: the study.ini of every other study is as it was
        text += "runs = auto\nprecision = " + format_real(rule->precision) +
                "\nmax-runs = " + std::to_string(rule->max) +
                "\ninitial-runs = " + std::to_string(rule->initial) +
                "\nround-runs = " + std::to_string(rule->step) + '\n';
    } else {
        text += "runs = " + std::to_string(study.runs) + '\n';
    }
    text += "seed = " + std::to_string(study.seed) + '\n';
    text += "seeds = " + std::string(seed_mode_name(study.seeds)) + '\n';
    for (const auto& b : study.budgets)
        text += "budget = " + budget_text(b) + '\n';
    if (!study.protocol.empty()) // only then: the study.ini of every other study is as it was
        text += "protocol = " + study.protocol + '\n';
    for (const auto& plugin : study.plugins) // likewise
        text += "plugins = " + plugin + '\n';
    return text;
}

bool parse_study_file(std::string_view text, const std::string& origin, Study& study,
                      std::vector<std::string>& errors) {
    namespace po = boost::program_options;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") // a UTF-8 byte-order mark, as some editors write
        text.remove_prefix(3);
    const po::options_description options = study_options();
    StudyOptionReader reader(study);
    const std::size_t errors_before = errors.size();
    std::size_t malformed = 0;
    std::size_t well_formed = 0;
    for (const auto& line : logical_lines(text)) {
        const std::string where = origin + ":" + std::to_string(line.number);
        if (line.text.front() == '[') {
            errors.push_back(where + ": sections (" + quoted_excerpt(line.text) +
                             ") are not used in study files");
            ++malformed;
            continue;
        }
        if (line.text.find('=') == std::string::npos) {
            errors.push_back(where + ": " + quoted_excerpt(line.text) + " is not key = value");
            ++malformed;
            continue;
        }
        ++well_formed;
        // Boost.Program_options reads the line (key, value, the option's name); one line at a
        // time, so that every error can name its line.
        std::istringstream stream(line.text + '\n');
        try {
            const po::parsed_options parsed = po::parse_config_file(stream, options, false);
            for (const auto& option : parsed.options)
                for (const auto& value : option.value)
                    reader.apply(option.string_key, trim(value), where, errors);
        } catch (const po::unknown_option&) {
            const std::string key = trim(std::string_view(line.text).substr(0, line.text.find('=')));
            std::string known;
            for (const auto& o : options.options())
                known += (known.empty() ? "" : ", ") + o->long_name();
            const bool run_only = key == "threads" || key == "out" || key == "overwrite" || key == "quiet";
            errors.push_back(where + ": unknown key " + quoted_excerpt(key) +
                             (run_only
                                  ? " (it is not part of a study: give --" + key + " on the command line)"
                                  : "; known: " + known));
        } catch (const po::error& e) {
            errors.push_back(where + ": " + e.what());
        }
    }
    if (malformed > 1 && well_formed == 0) {
        // Not a study file at all (another file given by mistake, or garbage): one line, not one a
        // line of it.
        const std::string first = errors[errors_before];
        errors.resize(errors_before);
        errors.push_back(origin + ": is not a study file (no line is key = value; line " +
                         first.substr(origin.size() + 1) + ", and " + std::to_string(malformed - 1) +
                         " more like it)");
        return false;
    }
    reader.finish(errors);
    return malformed == 0;
}

Study parse_study_ini(std::string_view text, const std::string& origin) {
    Study study;
    std::vector<std::string> errors;
    parse_study_file(text, origin, study, errors);
    if (!errors.empty()) {
        std::string joined;
        for (const auto& e : errors)
            joined += (joined.empty() ? "" : "\n") + e;
        throw std::invalid_argument(joined);
    }
    return study;
}

std::string read_study_text(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw std::runtime_error(path.string() + ": is a directory, not a study file (try " +
                                 (path / "study.ini").string() + ")");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path.string() + ": cannot be read (" + std::strerror(errno) + ")");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

Study read_study_file(const std::filesystem::path& path) {
    return parse_study_ini(read_study_text(path), path.string());
}

std::string study_file_summary(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    const auto end = std::min(text.find('\n'), text.size());
    const std::string first = trim(text.substr(0, end));
    return first.rfind('#', 0) == 0 ? trim(std::string_view(first).substr(1)) : std::string();
}

} // namespace mhb
