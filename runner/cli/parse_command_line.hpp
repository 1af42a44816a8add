// The command-line parsing every subcommand shares: Boost.Program_options with --help answered
// before required options are checked, so `mhbench <command> --help` always works.
#pragma once

#include <algorithm>
#include <boost/program_options.hpp>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/core/did_you_mean.hpp"
#include "problems/core/parameters.hpp"
#include "problems/core/text_excerpt.hpp"

namespace mhb::cli {

// "; did you mean '--threads'?" for an option the command does not have, when one of its options
// is near; empty otherwise.
inline std::string option_suggestion(const std::string& given,
                                     const boost::program_options::options_description& options) {
    const std::string bare = given.substr(std::min(given.find_first_not_of('-'), given.size()));
    std::vector<std::string> known;
    for (const auto& option : options.options())
        known.push_back(option->long_name());
    std::vector<std::string> near = closest_names(bare, known);
    for (auto& name : near)
        name = "--" + name;
    return near.empty() ? std::string() : "; " + did_you_mean(near);
}

// Parses `args` into `vm`. Returns false after calling `print_help` when --help (or -h) was given;
// otherwise notifies the options (which throws on a missing or malformed value) and returns true.
inline bool
parse_command_line(const std::vector<std::string>& args,
                   const boost::program_options::options_description& options,
                   boost::program_options::variables_map& vm, const std::function<void()>& print_help,
                   const boost::program_options::positional_options_description* positional = nullptr) {
    namespace po = boost::program_options;
    po::command_line_parser parser(args);
    parser.options(options);
    if (positional != nullptr)
        parser.positional(*positional);
    try {
        po::store(parser.run(), vm);
    } catch (const po::unknown_option& e) {
        throw po::error(e.what() + option_suggestion(e.get_option_name(), options));
    }
    if (vm.count("help") != 0) {
        print_help();
        return false;
    }
    po::notify(vm);
    return true;
}

// The integer option `--name` given as `text`, in [min, max]; otherwise std::invalid_argument in one
// line that quotes the text and says what is allowed.
inline long long integer_argument(const std::string& text, const char* name, long long min, long long max) {
    long long v = 0;
    if (!parse_integer(text, v))
        throw std::invalid_argument(std::string("--") + name + " = " + value_excerpt(text) + " " +
                                    integer_refusal(text, min, max));
    if (v < min || v > max)
        throw std::invalid_argument(std::string("--") + name + " = " + value_excerpt(text) + " is outside [" +
                                    std::to_string(min) + ", " + std::to_string(max) + "]");
    return v;
}

} // namespace mhb::cli
