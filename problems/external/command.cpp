#include "problems/external/command.hpp"

#include <filesystem>
#include <stdexcept>

#include "problems/core/process/executable_path.hpp"
#include "problems/core/sha256.hpp"

namespace mhb::external {

std::vector<std::string> split_command(const std::string& whole) {
    // cmd='python3 model.py' quotes the whole command so that a spec list keeps it one spec
    // (spec_grid.hpp): those outer quotes are not part of it.
    std::string text = whole;
    if (text.size() >= 2 && (text.front() == '\'' || text.front() == '"') && text.back() == text.front() &&
        text.find(text.front(), 1) == text.size() - 1)
        text = text.substr(1, text.size() - 2);
    std::vector<std::string> words;
    std::string word;
    bool in_word = false;
    char quote = 0;
    for (const char c : text) {
        if (quote != 0) {
            if (c == quote)
                quote = 0;
            else
                word += c;
        } else if (c == '\'' || c == '"') {
            quote = c;
            in_word = true;
        } else if (c == ' ' || c == '\t') {
            if (in_word)
                words.push_back(word);
            word.clear();
            in_word = false;
        } else {
            word += c;
            in_word = true;
        }
    }
    if (quote != 0)
        throw std::invalid_argument("external: cmd '" + text + "' has an unclosed quote");
    if (in_word)
        words.push_back(word);
    if (words.empty())
        throw std::invalid_argument("external: cmd is empty");
    return words;
}

namespace {

bool is_file(const std::string& word) {
    std::error_code error;
    return std::filesystem::is_regular_file(word, error);
}

// The words, as written, that name an existing file, without an installed interpreter in front.
std::vector<std::string> code_words(const std::vector<std::string>& words) {
    const std::string& first = words.front();
    const bool installed =
        first.find('/') == std::string::npos || first.starts_with("/usr/") || first.starts_with("/bin/");
    std::vector<std::string> files;
    for (std::size_t i = installed ? 1 : 0; i < words.size(); ++i)
        if (is_file(words[i]))
            files.push_back(words[i]);
    return files;
}

} // namespace

std::vector<std::string> code_files(const std::vector<std::string>& words) {
    std::vector<std::string> files = code_words(words);
    if (files.empty()) {
        // `cmd=mymodel` found in PATH: its executable is all there is.
        const std::string path = process::find_executable(words.front()).value_or(std::string());
        if (!path.empty() && is_file(path))
            files.push_back(path);
    }
    return files;
}

std::string program_name(const std::vector<std::string>& words) {
    if (words.empty())
        return {};
    const std::vector<std::string> code = code_words(words);
    return code.empty() ? words.front() : code.front();
}

std::map<std::string, std::string> split_params(const std::string& owner, const std::string& text) {
    std::map<std::string, std::string> out;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find(';', start), text.size());
        const std::string item = text.substr(start, end - start);
        start = end + 1;
        if (item.empty())
            continue;
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            throw std::invalid_argument(owner + ": params item '" + item + "' is not key=value");
        out[item.substr(0, eq)] = item.substr(eq + 1);
    }
    return out;
}

std::string identity_facts(const std::vector<std::string>& words, const std::string& version) {
    std::string facts;
    for (const auto& file : code_files(words))
        facts += "sha256 " + sha256_file_hex(file) + " " + file + "; ";
    return facts + "version " + version;
}

std::vector<ParameterInfo> common_parameters() {
    return {ParameterInfo::text(
                "cmd", "", "the program and its arguments, split at blanks (no shell; quote with '...')"),
            ParameterInfo::text("params", "",
                                "key=value;... passed to the program (describe and start messages)"),
            ParameterInfo::real("startup_timeout", 10, 0, 86400, "seconds allowed for starting and describe")
                .open_below()};
}

CommonOptions common_options(const ParameterValues& values) {
    if (!values.has("cmd"))
        throw std::invalid_argument("external: parameter 'cmd' is missing (external:cmd=program args...)");
    CommonOptions o;
    o.argv = split_command(values.text("cmd"));
    for (const auto& word : o.argv)
        o.command += (o.command.empty() ? "" : " ") + word;
    if (values.has("params"))
        o.parameters = split_params("external", values.text("params"));
    o.startup_timeout = std::chrono::duration<double>(values.real("startup_timeout"));
    return o;
}

} // namespace mhb::external
